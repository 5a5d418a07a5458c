/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Application
    dpiUnitTests

Description
    GoogleTest driver for the library's unit tests (models in isolation).
    Each TEST lives in its own *Test.C file listed in Make/files.
    OpenFOAM's Info is silenced unless DPI_TEST_VERBOSE is set, so the
    output is GoogleTest's own.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "IOstreams.H"
#include "Pstream.H"
#include <cstdlib>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    if (!std::getenv("DPI_TEST_VERBOSE"))
    {
        Foam::messageStream::level = 0;
    }
    return RUN_ALL_TESTS();
}

// ************************************************************************* //
