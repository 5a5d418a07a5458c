/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiSubStepForces.H"
#include "demState.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiSubStepForces::dpiSubStepForces
(
    const PtrList<dpiFluidForce>& forces,
    const dpiTurbulentDispersion* dispersion,
    const label n,
    const List<vectorField>& vecIn,
    const List<scalarField>& scaIn,
    const scalar dt,
    const label nSub,
    const label refresh,
    const label timeIndex
)
:
    forces_(forces),
    dispersion_(dispersion),
    n_(n),
    dt_(dt),
    nSub_(nSub),
    refresh_(refresh),
    timeIndex_(timeIndex),
    uInterval_(refresh > 1 ? n : 0, refresh),
    uNext_(refresh > 1 ? n : 0, 0),
    fluid_(n),
    sgs_(n),
    key_(n, 0),
    Su_(refresh > 1 ? n : 0),
    Sp_(refresh > 1 ? n : 0),
    SuCoupled_(refresh > 1 ? n : 0),
    SpCoupled_(refresh > 1 ? n : 0),
    impulse_(n, Zero),
    spImpulse_(n, 0)
{
    namespace col = fluidColumns;
    for (label i = 0; i < n; ++i)
    {
        dpiFluidForce::fluidState& fl = fluid_[i];
        fl.U = vecIn[col::U][i];
        fl.Uturb = vecIn[col::Uturb][i];
        fl.gradp = vecIn[col::gradp][i];
        fl.alpha = scaIn[col::alpha][i];
        fl.rho = scaIn[col::rho][i];
        fl.nu = scaIn[col::nu][i];
        sgs_[i].k = scaIn[col::k][i];
        sgs_[i].tau = scaIn[col::tau][i];
        key_[i] = label(scaIn[col::key][i]);
        fl.gasFree = (scaIn[col::gasFree][i] > 0.5);
    }

    // u* held over at most a tenth of its time scale (see the header)
    if (refresh > 1 && dispersion_)
    {
        for (label i = 0; i < n; ++i)
        {
            const scalar tau = sgs_[i].tau;
            if (tau > 0)
            {
                const scalar steps = 0.1*tau/dt;
                uInterval_[i] =
                    steps >= refresh ? refresh : max(label(1), label(steps));
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dpiSubStepForces::setForces(const label sub, demState& s)
{
    if (refresh_ == 1)
    {
        // The reference: everything at every sub-step
        vector Fc;
        scalar Spc;
        for (label i = 0; i < n_; ++i)
        {
            dpiFluidForce::fluidState& fl = fluid_[i];
            if (dispersion_)
            {
                fl.Uturb = dispersion_->update
                (
                    fl.Uturb, sgs_[i], dt_, key_[i], timeIndex_, sub + 1
                );
            }
            dpiFluidForce::sum
            (
                forces_, fl, s.v[i], 2*s.r[i], s.N[i], s.fExt[i], Fc, Spc
            );
            impulse_[i] += dt_*Fc;
            spImpulse_[i] += dt_*Spc;
        }
        return;
    }

    // u* of the rows due, over their coming interval (the last may be
    // shorter), drawn with the key of the interval's first sub-step
    if (dispersion_)
    {
        for (label i = 0; i < n_; ++i)
        {
            if (uNext_[i] == sub)
            {
                const label nU = min(uInterval_[i], nSub_ - sub);
                fluid_[i].Uturb = dispersion_->update
                (
                    fluid_[i].Uturb, sgs_[i], nU*dt_, key_[i],
                    timeIndex_, sub + 1
                );
                uNext_[i] = sub + nU;
            }
        }
    }

    // The forces' linearisation at the current velocity
    if (sub % refresh_ == 0)
    {
        for (label i = 0; i < n_; ++i)
        {
            dpiFluidForce::linearise
            (
                forces_, fluid_[i], s.v[i], 2*s.r[i], s.N[i],
                Su_[i], Sp_[i], SuCoupled_[i], SpCoupled_[i]
            );
        }
    }

    for (label i = 0; i < n_; ++i)
    {
        const dpiFluidForce::fluidState& fl = fluid_[i];
        const vector slip(fl.U + fl.Uturb - s.v[i]);
        s.fExt[i] = Su_[i] + Sp_[i]*slip;
        impulse_[i] += dt_*(SuCoupled_[i] + SpCoupled_[i]*slip);
        spImpulse_[i] += dt_*SpCoupled_[i];
    }
}


Foam::vectorField Foam::dpiSubStepForces::uStar() const
{
    vectorField u(n_);
    forAll(u, i)
    {
        u[i] = fluid_[i].Uturb;
    }
    return u;
}


// ************************************************************************* //
