/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "wallContacts.H"
#include "pairScaling.H"
#include <algorithm>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Law>
void Foam::wallContacts::rowForces
(
    const Law& law,
    const demState& s,
    const label p,
    const label first,
    const label last,
    const demMaterials& materials,
    const scalar dt,
    const bool advance,
    contactHistory& h,
    demDiagnostics& diag
)
{
    contrib_.clear();
    new_.clear();

    const scalar rp = s.r[p];

    DynamicList<contactHistory::wallContact>& old = h.wallState(p);

    if (first == last)
    {
        if (advance)
        {
            old.clear();
        }
        return;
    }

    const scalar S = pairScaling::wall(s.N[p]);

    demContact c;
    c.wall = true;
    // A re-evaluation also takes the trial step xi + v_s dt (a new contact
    // must not start in the sticking branch with its dashpot) but keeps it
    // only when advancing
    c.dt = dt;
    c.Rstar = rp;
    c.mstar = s.m[p];
    c.typei = s.typeId[p];
    c.ri = rp;
    c.rj = 0;
    c.cj = 0;
    c.omegaRel = s.omega[p];

    for (label b = first; b < last; ++b)
    {
        const demWallContact& wc = buf_[b];
        const label w = bufWall_[b];

        c.n = wc.n;
        c.delta = rp - wc.distance;
        c.props = &materials.pair(s.typeId[p], material_[w]);
        c.typej = material_[w];

        contribution con;
        con.partnerKey = contactHistory::wallPartnerKey(w, wc.key);
        con.f = Zero;
        con.t = Zero;

        if (!c.touching())
        {
            if (law.separated(c, S, con.f))
            {
                contrib_.append(con);
            }
            continue;
        }

        c.a = sqrt(c.Rstar*c.delta);
        c.ci = rp - 0.5*c.delta;
        c.vn = s.v[p] & c.n;
        c.vs = (s.v[p] - c.vn*c.n) - ((c.ci*s.omega[p]) ^ c.n);

        // The contact's history: same key, else a contact of the same
        // wall that just moved to a neighbouring triangle (normals
        // nearly parallel), else a new contact
        vector xi(Zero);
        label match = -1;
        forAll(old, o)
        {
            if (old[o].wall == w && old[o].key == wc.key)
            {
                match = o;
                break;
            }
        }
        if (match < 0)
        {
            scalar best = 0.9;
            forAll(old, o)
            {
                if (old[o].wall == w && (old[o].n & c.n) > best)
                {
                    bool taken = false;
                    for (const contactHistory::wallContact& nw : new_)
                    {
                        taken = taken
                         || (nw.wall == w && nw.key == old[o].key);
                    }
                    if (!taken)
                    {
                        best = old[o].n & c.n;
                        match = o;
                    }
                }
            }
        }
        if (match >= 0)
        {
            xi = old[match].xi;
        }

        vector Tj;
        law.touching(c, S, xi, con.f, con.t, Tj);
        contrib_.append(con);

        if (advance)
        {
            if (diag.stats && p < s.owned())
            {
                diag.stats->add
                (
                    diag.stats->wallClass(c.typei, c.typej),
                    match < 0,
                    con.f & c.n,
                    dt
                );
            }
            contactHistory::wallContact st;
            st.wall = w;
            st.key = wc.key;
            st.n = c.n;
            st.xi = xi;
            new_.append(st);
        }

        if (p < s.owned())
        {
            ++diag.nWallContacts;
            diag.record(c.delta/rp, -c.vn, s.globalId[p], -1 - w);
        }
    }

    if (advance)
    {
        old = new_;
    }

    std::sort
    (
        contrib_.begin(),
        contrib_.end(),
        [](const contribution& a, const contribution& b)
        {
            return a.partnerKey < b.partnerKey;
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Law>
void Foam::wallContacts::forces
(
    const Law& law,
    const demState& s,
    const demMaterials& materials,
    const scalar dt,
    const bool advance,
    contactHistory& h,
    List<vector>& f,
    List<vector>& t,
    demDiagnostics& diag
)
{
    if (walls_.empty())
    {
        return;
    }

    // The contacts of every near-wall row are found first, then their
    // laws evaluated: apart, one row's search (closest points, square
    // roots, the normals' divisions) and the next row's law do not wait on
    // each other, which they did in a single pass of search then law
    const label nWalls = walls_.size();
    buf_.clear();
    bufWall_.clear();
    bufStart_.setSize(nearWall_.size() + 1);
    forAll(nearWall_, k)
    {
        const label p = nearWall_[k];
        bufStart_[k] = buf_.size();
        forAll(walls_, w)
        {
            const label first = candStart_[p*nWalls + w];
            const label nCand = candStart_[p*nWalls + w + 1] - first;
            if (nCand)
            {
                walls_[w].findContacts
                (
                    s.x[p],
                    s.r[p] + law.maxRange(s.r[p]),
                    SubList<label>(cand_, nCand, first),
                    buf_
                );
                while (bufWall_.size() < buf_.size())
                {
                    bufWall_.append(w);
                }
            }
        }
    }
    bufStart_[nearWall_.size()] = buf_.size();

    forAll(nearWall_, k)
    {
        const label p = nearWall_[k];
        rowForces
        (
            law, s, p, bufStart_[k], bufStart_[k + 1], materials, dt,
            advance, h, diag
        );
        for (const contribution& con : contrib_)
        {
            f[p] += con.f;
            t[p] += con.t;
        }
    }
}


// ************************************************************************* //
