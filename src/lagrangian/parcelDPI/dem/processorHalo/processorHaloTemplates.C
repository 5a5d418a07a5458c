/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "PstreamBuffers.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::processorHalo::exchange(List<Type>& rowValues) const
{
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    forAll(sendRows_, proci)
    {
        if (sendRows_[proci].size())
        {
            UOPstream os(proci, pBufs);
            os << List<Type>(UIndirectList<Type>(rowValues, sendRows_[proci]));
        }
    }

    pBufs.finishedSends();

    forAll(recvSize_, proci)
    {
        if (recvSize_[proci])
        {
            UIPstream is(proci, pBufs);
            const List<Type> values(is);
            forAll(values, k)
            {
                rowValues[recvStart_[proci] + k] = values[k];
            }
        }
    }
}


// ************************************************************************* //
