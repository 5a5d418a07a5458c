/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "pairContacts.H"
#include "pairScaling.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Law>
void Foam::pairContacts::forces
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
) const
{
    const label nOwned = s.owned();
    List<vector>& nearXi = h.nearXi();
    List<bool>& nearHasXi = h.nearHasXi();

    demContact c;
    c.wall = false;
    // A re-evaluation also takes the trial step xi + v_s dt (a new contact
    // must not start in the sticking branch with its dashpot) but keeps it
    // only when advancing
    c.dt = dt;

    // Pairs out of range add nothing: adding zeros would not change a sum
    // (which is never -0, starting from +0), so skipping them changes no bit
    // (nor does leaving them out of the near list).
    // The partners' positions are read in no spatial order (the rows are
    // in the cloud's order): ask for them a few pairs ahead
    const label nNear = nearJ_.size();
    const label ahead = 16;

    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        const point xi0 = s.x[i];

        for (label m = nearStart_[a]; m < nearStart_[a + 1]; ++m)
        {
            if (m + ahead < nNear)
            {
                __builtin_prefetch(&s.x[nearJ_[m + ahead]]);
            }

            const label j = nearJ_[m];

            const vector d(xi0 - s.x[j]);
            const scalar r2 = magSqr(d);

            if (r2 >= nearCut2_[m])
            {
                if (advance && nearHasXi[m])
                {
                    nearXi[m] = Zero;
                    nearHasXi[m] = false;
                }
                continue;
            }

            const scalar rSum = s.r[i] + s.r[j];
            const scalar r = sqrt(r2);
            c.n = d/r;
            c.delta = rSum - r;
            c.props = &materials.pair(s.typeId[i], s.typeId[j]);
            c.typei = s.typeId[i];
            c.typej = s.typeId[j];
            c.ri = s.r[i];
            c.rj = s.r[j];
            c.Rstar = s.r[i]*s.r[j]/rSum;
            c.mstar = s.m[i]*s.m[j]/(s.m[i] + s.m[j]);

            const scalar S = pairScaling::pair(s.N[i], s.N[j]);
            if (!c.touching())
            {
                if (advance && nearHasXi[m])
                {
                    nearXi[m] = Zero;
                    nearHasXi[m] = false;
                }
                vector F;
                if (law.separated(c, S, F))
                {
                    f[i] += F;
                    f[j] -= F;
                }
                continue;
            }

            c.ci = s.r[i] - 0.5*c.delta;
            c.cj = s.r[j] - 0.5*c.delta;
            const vector vr(s.v[i] - s.v[j]);
            c.vn = vr & c.n;
            c.vs =
                (vr - c.vn*c.n) - ((c.ci*s.omega[i] + c.cj*s.omega[j]) ^ c.n);
            c.omegaRel = s.omega[i] - s.omega[j];

            vector xi(nearXi[m]);
            vector F, Ti, Tj;
            law.touching(c, S, xi, F, Ti, Tj);
            if (advance)
            {
                nearXi[m] = xi;
                nearHasXi[m] = true;
            }

            f[i] += F;
            t[i] += Ti;
            f[j] -= F;
            t[j] += Tj;

            // Each pair counted once over all processors: where the row of
            // the smaller globalId (i) is owned
            if (i < nOwned)
            {
                ++diag.nPairContacts;
                diag.record(c.delta/c.Rstar, -c.vn, s.globalId[i], s.globalId[j]);
            }
        }
    }
}


// ************************************************************************* //
