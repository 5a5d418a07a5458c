/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiRemotePoints.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::dpiRemotePoints::add
(
    const UList<Type>& values,
    Field<Type>& field
) const
{
    if (!Pstream::parRun())
    {
        return;
    }

    const label myProc = Pstream::myProcNo();

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            const labelList& idx = held_[proci];
            labelList cells(idx.size());
            List<Type> vals(idx.size());
            forAll(idx, j)
            {
                cells[j] = cell_[idx[j]];
                vals[j] = values[idx[j]];
            }
            UOPstream os(proci, pBufs);
            os << cells << vals;
        }
    }
    pBufs.finishedSends();

    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UIPstream is(proci, pBufs);
            const labelList cells(is);
            const List<Type> vals(is);
            forAll(cells, j)
            {
                field[cells[j]] += vals[j];
            }
        }
    }
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::dpiRemotePoints::fetch
(
    const UList<Type>& field
) const
{
    tmp<Field<Type>> tvalues(new Field<Type>(size(), Zero));

    if (!Pstream::parRun())
    {
        return tvalues;
    }

    const label myProc = Pstream::myProcNo();

    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            const labelList& idx = held_[proci];
            labelList cells(idx.size());
            forAll(idx, j)
            {
                cells[j] = cell_[idx[j]];
            }
            UOPstream os(proci, requests);
            os << cells;
        }
    }
    requests.finishedSends();

    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UIPstream is(proci, requests);
            const labelList cells(is);
            List<Type> vals(cells.size());
            forAll(cells, j)
            {
                vals[j] = field[cells[j]];
            }
            UOPstream os(proci, answers);
            os << vals;
        }
    }
    answers.finishedSends();

    Field<Type>& values = tvalues.ref();
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UIPstream is(proci, answers);
            const List<Type> vals(is);
            const labelList& idx = held_[proci];
            forAll(idx, j)
            {
                values[idx[j]] = vals[j];
            }
        }
    }

    return tvalues;
}


// ************************************************************************* //
