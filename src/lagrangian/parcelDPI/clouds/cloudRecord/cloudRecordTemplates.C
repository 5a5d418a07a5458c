/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "cloudRecord.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

template<class ReadFunction>
void Foam::cloudRecord::readFields
(
    const Time& time,
    const word& cloudName,
    const ReadFunction& read
)
{
    // OpenFOAM's errors thrown for the read only, then as they were
    const bool throwing = FatalError.throwExceptions();
    const bool ioThrowing = FatalIOError.throwExceptions();
    auto restore = [&]()
    {
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(ioThrowing);
    };
    string missing;
    try
    {
        read();
    }
    catch (const IOerror& err)
    {
        restore();
        IOerror other(err);
        other.dontThrowExceptions();
        other.exit();
    }
    catch (const error& err)
    {
        restore();
        missing = err.message();
        if (missing.find("cannot find file") == string::npos)
        {
            error other(err);
            other.dontThrowExceptions();
            other.exit();
        }
    }
    restore();
    if (missing.size())
    {
        refuseMissingFields(time, cloudName, missing);
    }
}


// ************************************************************************* //
