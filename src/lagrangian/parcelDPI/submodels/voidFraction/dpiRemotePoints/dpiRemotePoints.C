/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiRemotePoints.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiRemotePoints::dpiRemotePoints()
:
    proc_(),
    cell_(),
    held_(Pstream::nProcs())
{}


Foam::dpiRemotePoints::dpiRemotePoints
(
    const polyMesh& mesh,
    const UList<point>& pts
)
:
    proc_(pts.size(), -1),
    cell_(pts.size(), -1),
    held_(Pstream::nProcs())
{
    if (!Pstream::parRun())
    {
        return;
    }

    const label myProc = Pstream::myProcNo();

    // Every other processor looks every point up
    PstreamBuffers queries(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UOPstream os(proci, queries);
            os << pts;
        }
    }
    queries.finishedSends();

    PstreamBuffers replies(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UIPstream is(proci, queries);
            const List<point> theirs(is);
            labelList cells(theirs.size());
            forAll(theirs, k)
            {
                // tets: the same containment test as the asking side's
                cells[k] = mesh.findCell(theirs[k], polyMesh::CELL_TETS);
            }
            UOPstream os(proci, replies);
            os << cells;
        }
    }
    replies.finishedSends();

    // Processors in increasing order: the lowest that finds a point holds it
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci != myProc)
        {
            UIPstream is(proci, replies);
            const labelList cells(is);
            forAll(cells, k)
            {
                if (cells[k] >= 0 && proc_[k] < 0)
                {
                    proc_[k] = proci;
                    cell_[k] = cells[k];
                }
            }
        }
    }

    labelList n(Pstream::nProcs(), 0);
    forAll(proc_, k)
    {
        if (proc_[k] >= 0)
        {
            ++n[proc_[k]];
        }
    }
    forAll(held_, proci)
    {
        held_[proci].setSize(n[proci]);
        n[proci] = 0;
    }
    forAll(proc_, k)
    {
        if (proc_[k] >= 0)
        {
            held_[proc_[k]][n[proc_[k]]++] = k;
        }
    }
}


// ************************************************************************* //
