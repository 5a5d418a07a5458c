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
    // Asked once: the sums below could alias diag for the compiler
    contactStatistics* const stats = advance ? diag.stats : nullptr;
    List<vector>& nearXi = h.nearXi();
    List<bool>& nearHasXi = h.nearHasXi();

    // Pairs out of range add nothing: adding zeros would not change a sum
    // (which is never -0, starting from +0), so skipping them changes no bit
    // (nor does leaving them out of the near list).
    //
    // Loops over a block of rows: the pairs within range are selected,
    // then their geometry computed in columns (the square roots and
    // divisions of two pairs per instruction), then the touching pairs'
    // velocities, then each pair's contact and law. With the geometry
    // inline in one loop per pair it formed one long chain per pair
    // (packed bed of 10,000 carriers: pair term 6.1 -> 4.9 s when split
    // out). The law loop takes the selected pairs in the
    // order of a single sweep, so every sum takes its terms in the same
    // order (bit-identical results).
    //
    // The partners' positions are read in no spatial order (the rows are
    // in the cloud's order): ask for them a few pairs ahead
    const label nNear = nearJ_.size();
    const label ahead = 16;
    const label nRows = pairRow_.size();

    // Near pairs per block: the block's selection, geometry and
    // kinematics columns (~120 bytes a pair) stay in the first-level cache
    const label blockPairs = 64;

    // The seats the parcels touch now, before any pair needs them
    if (knocks_)
    {
        findSeats(s);
    }
    const scalar share = cg_->knockShare();

    label a0 = 0;
    while (a0 < nRows)
    {
        // A block of whole rows of at most blockPairs near pairs (a
        // longer row alone)
        label a1 = a0 + 1;
        while
        (
            a1 < nRows
         && nearStart_[a1 + 1] - nearStart_[a0] <= blockPairs
        )
        {
            ++a1;
        }
        const label nBlock = nearStart_[a1] - nearStart_[a0];
        if (selectedM_.size() < nBlock)
        {
            selectedM_.setSize(nBlock);
            selectedI_.setSize(nBlock);
            dx_.setSize(nBlock);
            dy_.setSize(nBlock);
            dz_.setSize(nBlock);
            r2_.setSize(nBlock);
            rSum_.setSize(nBlock);
            Rstar_.setSize(nBlock);
            delta_.setSize(nBlock);
            a_.setSize(nBlock);
            ratio_.setSize(nBlock);
            vn_.setSize(nBlock);
            vs_.setSize(nBlock);
        }

        // The pairs within range, with the inputs of their geometry: the
        // separation the test computed is kept (gathered and subtracted
        // once), and the radius sum and R*
        label n = 0;
        for (label a = a0; a < a1; ++a)
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
                const bool in = !(r2 >= nearCut2_[m]);

                if (in)
                {
                    selectedM_[n] = m;
                    selectedI_[n] = i;
                    dx_[n] = d.x();
                    dy_[n] = d.y();
                    dz_[n] = d.z();
                    r2_[n] = r2;
                    rSum_[n] = nearRSum_[m];
                    Rstar_[n] = nearRstar_[m];
                    ++n;
                }
                else if (advance && nearHasXi[m])
                {
                    nearXi[m] = Zero;
                    nearHasXi[m] = false;
                }
            }
        }
        a0 = a1;

        // The selected pairs' square roots and divisions, column by column
        // (two pairs per instruction)
        columnGeometry(n);

        // The touching pairs' kinematics, in a loop of their own: each
        // iteration is short and independent of the others, so the
        // processor overlaps the velocity gathers of several pairs. In the
        // law loop they sat at the head of each pair's chain of dependent
        // arithmetic (slip, history, its magnitude, the sliding test).
        for (label k = 0; k < n; ++k)
        {
            if (!(delta_[k] > 0))
            {
                continue;
            }
            const label i = selectedI_[k];
            const label j = nearJ_[selectedM_[k]];
            const vector nk(dx_[k], dy_[k], dz_[k]);
            const scalar ci = s.r[i] - 0.5*delta_[k];
            const scalar cj = s.r[j] - 0.5*delta_[k];
            const vector vr(s.v[i] - s.v[j]);
            const scalar vn = vr & nk;
            vn_[k] = vn;
            vs_[k] = (vr - vn*nk) - ((ci*s.omega[i] + cj*s.omega[j]) ^ nk);
        }

        // Then each pair's contact and its law, in order. (The contact
        // is built where the law uses it: kept in a block's array between
        // two loops it cost its stores and loads, ~170 bytes a pair.)
        for (label k = 0; k < n; ++k)
        {
            const label m = selectedM_[k];
            const label i = selectedI_[k];
            const label j = nearJ_[m];

            demContact c;
            c.wall = false;
            // A re-evaluation also takes the trial step xi + v_s dt (a new
            // contact must not start in the sticking branch with its
            // dashpot) but keeps it only when advancing
            c.dt = dt;

            c.n = vector(dx_[k], dy_[k], dz_[k]);
            c.delta = delta_[k];
            c.a = a_[k];
            c.props = &materials.pair(s.typeId[i], s.typeId[j]);
            c.typei = s.typeId[i];
            c.typej = s.typeId[j];
            c.ri = s.r[i];
            c.rj = s.r[j];
            c.Rstar = Rstar_[k];
            c.mstar = nearMstar_[m];

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

            // The kinematics of a touching contact
            // The lever arms are the primaries' (also where two parcels
            // meet at grown radii: a parcel's spin is its primaries', each
            // rolling on its own radius). They then fall short of the
            // centre distance by the growth, so such a pair's friction
            // does not keep angular momentum about a fixed point; arms to
            // the grown contact point would, and measured worse (Case 6
            // at N = 10 detached 0.46 against N = 1's 0.63: doc/theory.md
            // 2.5)
            c.ci = s.r[i] - 0.5*c.delta;
            c.cj = s.r[j] - 0.5*c.delta;
            c.vn = vn_[k];
            c.vs = vs_[k];
            c.omegaRel = s.omega[i] - s.omega[j];

            vector xi(nearXi[m]);
            vector F, Ti, Tj;
            law.touching(c, S, xi, F, Ti, Tj);
            if (advance)
            {
                if (stats && i < nOwned)
                {
                    stats->add
                    (
                        stats->pairClass(c.typei, c.typej),
                        !nearHasXi[m],
                        F & c.n,
                        dt
                    );
                }
                nearXi[m] = xi;
                nearHasXi[m] = true;
            }

            // Knocks along the seat (coarseGrainingModel): the share of
            // the radial part (along each parcel's direction from the
            // seat's centre) of the normal force is moved to the seat,
            // along the same lines, so momentum and angular momentum are
            // kept
            const label seat =
                knocks_ && cg_->grown(c.typei, c.typej)
              ? commonSeat(s, i, j)
              : -1;
            if (seat >= 0)
            {
                const vector ei(normalised(s.x[i] - s.x[seat]));
                const vector ej(normalised(s.x[j] - s.x[seat]));
                const scalar fn = share*(F & c.n);
                const vector dfi(-fn*(c.n & ei)*ei);
                const vector dfj(fn*(c.n & ej)*ej);
                f[i] += F + dfi;
                f[j] += dfj - F;
                f[seat] -= dfi + dfj;
            }
            else
            {
                f[i] += F;
                f[j] -= F;
            }
            t[i] += Ti;
            t[j] += Tj;

            // Each pair counted once over all processors: where the row of
            // the smaller key (i) is owned; named by its ids in increasing
            // order, whichever the sweep took first
            if (i < nOwned)
            {
                ++diag.nPairContacts;
                const label a = s.globalId[i];
                const label b = s.globalId[j];
                diag.record(ratio_[k], -c.vn, min(a, b), max(a, b));
            }
        }
    }
}


// ************************************************************************* //
