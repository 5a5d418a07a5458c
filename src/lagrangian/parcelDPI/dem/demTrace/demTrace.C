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
#include "HashSet.H"
#include "PstreamCombineReduceOps.H"

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
    dictName_(dict.name()),
    warned_(ids_.size(), 0),
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


void Foam::demTrace::warnAbsent
(
    const labelUList& globalIds,
    const label nIssued,
    const word& timeName
)
{
    labelList present(ids_.size(), 0);
    const labelHashSet here(globalIds);
    forAll(ids_, i)
    {
        present[i] = here.found(ids_[i]);
    }
    Pstream::listCombineGather(present, maxEqOp<label>());
    Pstream::listCombineScatter(present);

    forAll(ids_, i)
    {
        if (present[i] || warned_[i])
        {
            continue;
        }
        warned_[i] = 1;
        WarningInFunction
            << "Entry 'parcels' of " << dictName_ << " names parcel "
            << ids_[i] << ", but no parcel carries that globalId at time "
            << timeName << " (" << nIssued << " ids issued: 0 to "
            << nIssued - 1 << "): nothing is traced for it unless a parcel"
            << " with that id is injected later" << endl;
    }
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
