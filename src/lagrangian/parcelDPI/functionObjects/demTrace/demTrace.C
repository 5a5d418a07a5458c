/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demTrace.H"
#include "dictKeys.H"
#include "demState.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::demTrace::findRow(const label i, const demState& s)
{
    const label hint = rows_[i];
    if (hint >= 0 && hint < s.size() && s.globalId[hint] == ids_[i])
    {
        return hint;
    }

    rows_[i] = -1;
    forAll(s.globalId, row)
    {
        if (s.globalId[row] == ids_[i])
        {
            rows_[i] = row;
            break;
        }
    }
    return rows_[i];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demTrace::demTrace(const dictionary& dict, const fileName& dir)
:
    dir_(dir),
    ids_(dict.get<labelList>("parcels")),
    rows_(ids_.size(), -1),
    files_(ids_.size()),
    t0_(0),
    dt_(0),
    k_(0)
{
    // The one key read above
    dictKeys::warnUnknown(dict, {"parcels"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demTrace::beginStep(const scalar t0, const scalar dt)
{
    t0_ = t0;
    dt_ = dt;
    k_ = 0;
}


void Foam::demTrace::subStep(const scalar, const demState& s)
{
    // Absolute time from a step count: no drift from summing dt
    ++k_;
    const scalar t = t0_ + k_*dt_;

    forAll(ids_, i)
    {
        const label row = findRow(i, s);
        if (row < 0)
        {
            continue;
        }

        if (!files_.set(i))
        {
            mkDir(dir_);
            files_.set
            (
                i,
                new OFstream(dir_/("parcel" + Foam::name(ids_[i]) + ".dat"))
            );
            files_[i].precision(17);
            files_[i]
                << "# time x y z vx vy vz fx fy fz omegax omegay omegaz"
                << nl;
        }

        OFstream& os = files_[i];
        const vector& x = s.x[row];
        const vector& v = s.v[row];
        const vector& f = s.f[row];
        const vector& w = s.omega[row];
        os  << t
            << ' ' << x.x() << ' ' << x.y() << ' ' << x.z()
            << ' ' << v.x() << ' ' << v.y() << ' ' << v.z()
            << ' ' << f.x() << ' ' << f.y() << ' ' << f.z()
            << ' ' << w.x() << ' ' << w.y() << ' ' << w.z()
            << nl;
    }
}


// ************************************************************************* //
