/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "triangleWall.H"
#include "boundBox.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace demWalls
{
    defineTypeNameAndDebug(triangleWall, 0);
    addToRunTimeSelectionTable(demWall, triangleWall, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demWalls::triangleWall::checkTriangles(const dictionary& dict) const
{
    if (tris_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name() << " in dictionary " << dict.name()
            << " has no triangles" << exit(FatalIOError);
    }

    if (tris_.size() >= maxKeys)
    {
        FatalIOErrorInFunction(dict)
            << "Wall " << name() << " has " << tris_.size()
            << " triangles; at most " << maxKeys << " per wall are "
            << "supported: split it into several walls" << exit(FatalIOError);
    }

    forAll(tris_, t)
    {
        for (const label v : tris_[t])
        {
            if (v < 0 || v >= points_.size())
            {
                FatalIOErrorInFunction(dict)
                    << "Triangle " << t << " " << tris_[t] << " of wall "
                    << name() << " refers to point " << v << " but there "
                    << "are " << points_.size() << " points"
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::triangleWall::triangleWall
(
    const word& name,
    const dictionary& dict,
    const polyMesh*
)
:
    triangleWall
    (
        name,
        dict,
        dict.get<pointField>("points"),
        dict.get<triFaceList>("triangles"),
        {"points", "triangles"}
    )
{}


Foam::demWalls::triangleWall::triangleWall
(
    const word& name,
    const dictionary& dict,
    pointField&& points,
    triFaceList&& tris,
    const wordList& typeKeys
)
:
    demWall(name, dict, typeKeys),
    points_(std::move(points)),
    tris_(std::move(tris)),
    cellSize_(0),
    origin_(Zero),
    nCells_{0, 0, 0},
    reach_(-1)
{
    checkTriangles(dict);

    planes_.setSize(tris_.size());
    forAll(tris_, t)
    {
        const triFace& f = tris_[t];
        const vector nf
        (
            (points_[f[1]] - points_[f[0]]) ^ (points_[f[2]] - points_[f[0]])
        );
        const scalar magNf = mag(nf);
        planes_[t].a = points_[f[0]];
        planes_[t].n = (magNf > VSMALL) ? nf/magNf : vector::zero;
        planes_[t].tol = 0;     // set by prepare
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::point Foam::demWalls::triangleWall::closestPoint
(
    const point& p,
    const point& a,
    const point& b,
    const point& c,
    feature& where,
    label& e
)
{
    // Voronoi regions of the triangle, tested vertex by vertex with the
    // barycentric sub-areas (Ericson, Real-Time Collision Detection 5.1.5)
    const vector ab(b - a);
    const vector ac(c - a);

    const vector ap(p - a);
    const scalar d1 = ab & ap;
    const scalar d2 = ac & ap;
    if (d1 <= 0 && d2 <= 0)
    {
        where = VERTEX; e = 0;
        return a;
    }

    const vector bp(p - b);
    const scalar d3 = ab & bp;
    const scalar d4 = ac & bp;
    if (d3 >= 0 && d4 <= d3)
    {
        where = VERTEX; e = 1;
        return b;
    }

    const scalar vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        where = EDGE; e = 0;
        return a + (d1/(d1 - d3))*ab;
    }

    const vector cp(p - c);
    const scalar d5 = ab & cp;
    const scalar d6 = ac & cp;
    if (d6 >= 0 && d5 <= d6)
    {
        where = VERTEX; e = 2;
        return c;
    }

    const scalar vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        where = EDGE; e = 2;
        return a + (d2/(d2 - d6))*ac;
    }

    const scalar va = d3*d6 - d5*d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        where = EDGE; e = 1;
        return b + ((d4 - d3)/((d4 - d3) + (d5 - d6)))*(c - b);
    }

    where = FACE; e = -1;
    const scalar denom = 1/(va + vb + vc);
    return a + (vb*denom)*ab + (vc*denom)*ac;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::demWalls::triangleWall::beyond(const boundBox& bb) const
{
    scalar d = 0;
    for (const point& p : points_)
    {
        d = max(d, mag(p - bb.nearest(p)));
    }
    return d;
}


void Foam::demWalls::triangleWall::prepare(const scalar reach)
{
    if (reach_ >= reach && !cells_.empty())
    {
        return;
    }

    reach_ = reach;
    cells_.clear();

    boundBox bb(points_, false);
    const point lo(bb.min() - vector::uniform(reach));
    const point hi(bb.max() + vector::uniform(reach));

    scalar meanEdge = 0;
    for (const triFace& f : tris_)
    {
        meanEdge +=
            mag(points_[f[1]] - points_[f[0]])
          + mag(points_[f[2]] - points_[f[1]])
          + mag(points_[f[0]] - points_[f[2]]);
    }
    meanEdge /= 3*tris_.size();

    // Cells no smaller than a sphere's reach (one cell lookup per query) and
    // no smaller than a typical triangle (few cells per triangle)
    cellSize_ = max(2*reach, meanEdge);

    const scalar span = cmptMax(hi - lo);
    const label maxCells = 2000000;
    cellSize_ = max(cellSize_, span/(maxCells - 2));
    cellSize_ = max(cellSize_, VSMALL);

    origin_ = lo;
    for (direction d = 0; d < 3; ++d)
    {
        nCells_[d] = label((hi[d] - lo[d])/cellSize_) + 1;
    }

    // Round-off of a plane distance is ~1e-16 of the distance from the
    // triangle's first vertex, which for a sphere that can be tested is
    // below the triangle's size plus two cells; 1e-12 of that is ample
    forAll(tris_, t)
    {
        const triFace& f = tris_[t];
        const scalar size = max
        (
            max
            (
                mag(points_[f[1]] - points_[f[0]]),
                mag(points_[f[2]] - points_[f[1]])
            ),
            mag(points_[f[0]] - points_[f[2]])
        );
        planes_[t].tol = 1e-12*(size + 2*cellSize_ + reach);
    }

    const scalar halfDiag = 0.5*sqrt(3.0)*cellSize_;

    forAll(tris_, t)
    {
        const triFace& f = tris_[t];
        const point& a = points_[f[0]];
        const point& b = points_[f[1]];
        const point& c = points_[f[2]];

        vector nf((b - a) ^ (c - a));
        const scalar magNf = mag(nf);
        nf = (magNf > VSMALL) ? nf/magNf : vector::zero;

        const point tlo(min(min(a, b), c) - vector::uniform(reach));
        const point thi(max(max(a, b), c) + vector::uniform(reach));

        label i0[3], i1[3];
        for (direction d = 0; d < 3; ++d)
        {
            i0[d] = max(label((tlo[d] - origin_[d])/cellSize_), 0);
            i1[d] =
                min(label((thi[d] - origin_[d])/cellSize_), nCells_[d] - 1);
        }

        for (label i = i0[0]; i <= i1[0]; ++i)
        {
            for (label j = i0[1]; j <= i1[1]; ++j)
            {
                for (label k = i0[2]; k <= i1[2]; ++k)
                {
                    // Only the cells the plane passes near
                    const point cc
                    (
                        origin_.x() + (i + 0.5)*cellSize_,
                        origin_.y() + (j + 0.5)*cellSize_,
                        origin_.z() + (k + 0.5)*cellSize_
                    );
                    if (mag((cc - a) & nf) <= halfDiag + reach)
                    {
                        cells_[cellKey(i, j, k)].push_back(t);
                    }
                }
            }
        }
    }
}


const std::vector<Foam::label>*
Foam::demWalls::triangleWall::cellOf(const point& x) const
{
    label ijk[3];
    for (direction d = 0; d < 3; ++d)
    {
        const scalar s = (x[d] - origin_[d])/cellSize_;
        if (s < 0 || s >= nCells_[d])
        {
            return nullptr;
        }
        ijk[d] = label(s);
    }

    const auto iter = cells_.find(cellKey(ijk[0], ijk[1], ijk[2]));
    if (iter == cells_.end())
    {
        return nullptr;
    }

    return &iter->second;
}


void Foam::demWalls::triangleWall::checkReach(const scalar reach) const
{
    // The triangle grid was built for reach_: a larger query would miss
    // triangles in the neighbouring grid cells
    if (reach > reach_)
    {
        FatalErrorInFunction
            << "Wall " << name() << " was prepared for a reach of " << reach_
            << " m but is asked for " << reach << " m" << abort(FatalError);
    }
}


void Foam::demWalls::triangleWall::findContacts
(
    const point& x,
    const scalar reach,
    DynamicList<demWallContact>& contacts
) const
{
    checkReach(reach);

    const std::vector<label>* cell = cellOf(x);
    if (cell && cell->size())
    {
        contactsOf
        (
            x, reach, cell->data(), cell->data() + cell->size(), contacts
        );
    }
}


void Foam::demWalls::triangleWall::findCandidates
(
    const point& x,
    const scalar reach,
    DynamicList<label>& elements
) const
{
    checkReach(reach);

    const std::vector<label>* cell = cellOf(x);
    if (!cell)
    {
        return;
    }

    for (const label t : *cell)
    {
        if (outOfReach(t, x, reach))
        {
            continue;
        }
        const triFace& f = tris_[t];
        feature where;
        label e;
        const point q = closestPoint
        (
            x, points_[f[0]], points_[f[1]], points_[f[2]], where, e
        );
        if (mag(x - q) < reach)
        {
            elements.append(t);
        }
    }
}


void Foam::demWalls::triangleWall::findContacts
(
    const point& x,
    const scalar reach,
    const labelUList& elements,
    DynamicList<demWallContact>& contacts
) const
{
    if (elements.size())
    {
        contactsOf
        (
            x, reach, elements.cdata(), elements.cdata() + elements.size(),
            contacts
        );
    }
}


void Foam::demWalls::triangleWall::contactsOf
(
    const point& x,
    const scalar reach,
    const label* first,
    const label* last,
    DynamicList<demWallContact>& contacts
) const
{
    work_.clear();

    for (const label* tp = first; tp != last; ++tp)
    {
        const label t = *tp;

        // Most triangles of a cell, or of a candidate list, are out of
        // reach: their plane is
        if (outOfReach(t, x, reach))
        {
            continue;
        }

        const triFace& f = tris_[t];
        feature where;
        label e;
        const point q = closestPoint
        (
            x, points_[f[0]], points_[f[1]], points_[f[2]], where, e
        );

        const scalar d = mag(x - q);
        if (d >= reach)
        {
            continue;
        }

        candidate cand;
        cand.tri = t;
        cand.where = where;
        cand.q = q;
        cand.distance = d;
        cand.v0 = -1;
        cand.v1 = -1;
        if (where == EDGE)
        {
            cand.v0 = min(f[e], f[(e + 1) % 3]);
            cand.v1 = max(f[e], f[(e + 1) % 3]);
        }
        else if (where == VERTEX)
        {
            cand.v0 = f[e];
        }
        work_.append(cand);
    }

    // The same point seen from two triangles differs by round-off only
    const scalar tol = 1e-9*reach;
    const scalar tol2 = sqr(tol);

    kept_.clear();

    forAll(work_, ci)
    {
        const candidate& c = work_[ci];
        bool keep = true;

        // An edge or vertex contact is a contact only if it is a local
        // minimum of the distance: no triangle sharing that edge or vertex
        // has its closest point elsewhere (which would be closer, the
        // closest point of a triangle being unique)
        if (c.where != FACE)
        {
            forAll(work_, ui)
            {
                const candidate& u = work_[ui];
                const triFace& fu = tris_[u.tri];

                if
                (
                    ui != ci
                 && fu.found(c.v0) && (c.v1 < 0 || fu.found(c.v1))
                 && magSqr(u.q - c.q) > tol2
                )
                {
                    keep = false;
                    break;
                }
            }
        }

        // A point already reported (a shared edge or vertex, or a point on
        // an edge that round-off puts inside both faces) counts once
        if (keep)
        {
            for (const label ki : kept_)
            {
                if (magSqr(work_[ki].q - c.q) <= tol2)
                {
                    keep = false;
                    break;
                }
            }
        }

        if (keep)
        {
            kept_.append(ci);

            demWallContact wc;
            wc.key = c.tri;
            wc.distance = c.distance;
            if (c.distance > VSMALL)
            {
                wc.n = (x - c.q)/c.distance;
            }
            else
            {
                // Centre on the surface: fall back to the face normal
                const triFace& f = tris_[c.tri];
                const vector nf
                (
                    (points_[f[1]] - points_[f[0]])
                  ^ (points_[f[2]] - points_[f[0]])
                );
                wc.n = nf/(mag(nf) + VSMALL);
            }
            contacts.append(wc);
        }
    }
}


// ************************************************************************* //
