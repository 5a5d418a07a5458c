/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiVoidFraction.H"
#include "dictKeys.H"
#include "polyMesh.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiVoidFraction, 0);
    defineRunTimeSelectionTable(dpiVoidFraction, dictionary);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::scalar Foam::dpiVoidFraction::readAlphaMin(const dictionary& dict)
{
    const scalar alphaMin = dict.getOrDefault<scalar>("alphaMin", 0.3);

    if (!(alphaMin > 0 && alphaMin < 1))
    {
        FatalIOErrorInFunction(dict)
            << "voidFraction/alphaMin = " << alphaMin << " in "
            << dict.name() << " must lie in (0, 1): it is the floor of the"
            << " gas void fraction (the reference decks use 0.3)"
            << exit(FatalIOError);
    }

    if (dict.found("scaleUpVol"))
    {
        FatalIOErrorInFunction(dict)
            << "voidFraction/scaleUpVol is not supported: it has no effect"
            << " in the reference code (theory 9.12). Remove it from "
            << dict.name() << exit(FatalIOError);
    }

    return alphaMin;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiVoidFraction::dpiVoidFraction
(
    const dictionary& dict,
    const wordList& modelKeys
)
:
    dict_(dict),
    alphaMin_(readAlphaMin(dict))
{
    // type is read by the selector New; the retired scaleUpVol has its
    // own error in readAlphaMin
    wordList known({"type", "alphaMin"});
    known.append(modelKeys);
    dictKeys::warnUnknown(dict, known);
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dpiVoidFraction>
Foam::dpiVoidFraction::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("type"));

    Info<< "Selecting void fraction model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown void fraction model " << modelType << " in "
            << dict.name() << nl << nl << "Valid void fraction models :"
            << nl << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<dpiVoidFraction>(cstrIter()(dict));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::vectorList& Foam::dpiVoidFraction::unitPoints()
{
    static vectorList pts;

    if (pts.empty())
    {
        // Radii of the two shells' points (theory 5.1)
        const scalar radii[2] = {0.623926, 0.917902};
        const scalar s = 1/Foam::sqrt(2.0);

        pts.setSize(nPoints);
        label n = 0;
        pts[n++] = Zero;
        for (const scalar r : radii)
        {
            pts[n++] = vector(r, 0, 0);
            pts[n++] = vector(-r, 0, 0);
            pts[n++] = vector(0, r, 0);
            pts[n++] = vector(0, -r, 0);
            pts[n++] = vector(0, 0, r);
            pts[n++] = vector(0, 0, -r);
            for (const scalar sz : {s, -s})
            {
                for (const scalar sx : {0.5, -0.5})
                {
                    for (const scalar sy : {0.5, -0.5})
                    {
                        pts[n++] = r*vector(sx, sy, sz);
                    }
                }
            }
        }
    }

    return pts;
}


void Foam::dpiVoidFraction::pointWeights
(
    const polyMesh& mesh,
    const point& x,
    const label celli,
    const scalar R,
    DynamicList<label>& cells,
    DynamicList<scalar>& weights,
    DynamicList<point>* unresolved
)
{
    cells.clear();
    weights.clear();
    if (unresolved)
    {
        unresolved->clear();
    }

    const vectorList& pts = unitPoints();
    const scalar rOut = 0.917902*R;

    // Cheap case: the sphere of the outer points lies inside the cell
    // (distance to every face plane >= rOut; exact for planar faces)
    {
        const cell& c = mesh.cells()[celli];
        bool inside = true;
        for (const label facei : c)
        {
            vector n = mesh.faceAreas()[facei];
            n /= mag(n);
            if (mesh.faceOwner()[facei] != celli)
            {
                n = -n;
            }
            if (((mesh.faceCentres()[facei] - x) & n) < rOut)
            {
                inside = false;
                break;
            }
        }

        if (inside)
        {
            cells.append(celli);
            weights.append(1);
            return;
        }
    }

    const labelList& nbrs = mesh.cellCells()[celli];
    const scalar wPt = 1.0/nPoints;

    for (const vector& u : pts)
    {
        const point pt(x + R*u);

        // The cell whose tets hold the point: the tets of a valid mesh
        // tile it, so the answer is unique and the same whichever
        // processor asks (the face planes of a warped cell overlap its
        // neighbour's, which made a point near a processor boundary go to
        // a cell on this side in parallel and across it in serial)
        label cellj = -1;
        if (mesh.pointInCell(pt, celli, polyMesh::CELL_TETS))
        {
            cellj = celli;
        }
        else
        {
            for (const label nbr : nbrs)
            {
                if (mesh.pointInCell(pt, nbr, polyMesh::CELL_TETS))
                {
                    cellj = nbr;
                    break;
                }
            }
            if (cellj < 0)
            {
                cellj = mesh.findCell(pt, polyMesh::CELL_TETS);
            }
            if (cellj < 0)
            {
                if (unresolved)
                {
                    // Maybe another processor's: the caller decides
                    unresolved->append(pt);
                    continue;
                }
                // Outside the mesh: the centre's cell
                cellj = celli;
            }
        }

        // Merge repeated cells (a parcel spans a few cells at most)
        const label k = cells.find(cellj);
        if (k < 0)
        {
            cells.append(cellj);
            weights.append(wPt);
        }
        else
        {
            weights[k] += wPt;
        }
    }

    // The caller gives the points no processor holds to the centre's cell
    if (unresolved && unresolved->size() && !cells.found(celli))
    {
        cells.append(celli);
        weights.append(0);
    }
}


void Foam::dpiVoidFraction::distribute
(
    const polyMesh& mesh,
    const point& x,
    const label celli,
    const scalar R,
    const scalar Vs,
    scalarField& solidVolume
)
{
    DynamicList<label> cells;
    DynamicList<scalar> weights;

    pointWeights(mesh, x, celli, R, cells, weights);

    forAll(cells, k)
    {
        solidVolume[cells[k]] += weights[k]*Vs;
    }
}


// ************************************************************************* //
