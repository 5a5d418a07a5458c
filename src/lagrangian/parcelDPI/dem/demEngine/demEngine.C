/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demEngine.H"
#include <cmath>
#include "pairScaling.H"
#include "demContact.H"
#include "dictKeys.H"
#include "polyMesh.H"
#include "IOmanip.H"
#include "Map.H"
#include <algorithm>
#include <chrono>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demEngine, 0);
}


const Foam::wordList Foam::demEngine::keys
({
    "timeStep",
    "types",
    "pairs",
    "normalModel",
    "tangentialModel",
    "rollingModel",
    "cohesionModel",
    "walls",
    "neighbourSearch",
    "timeStepCheck",
    "startOverlap",
    "overlapCheck",
    "loadBalance"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Wall-clock seconds since an arbitrary origin
inline double wallClock()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}

//- Walls are packed with 7 bits in the history partner key
const Foam::label maxWalls = 128;

//- The model families of the engine: the selecting key and whether a model
//  of that name exists in the family (for <model>Coeffs of a model that is
//  not selected)
struct modelFamily
{
    const char* key;
    bool (*exists)(const Foam::word& model);
};

template<class Model>
bool modelExists(const Foam::word& model)
{
    return
        Model::dictionaryConstructorTablePtr_
     && Model::dictionaryConstructorTablePtr_->found(model);
}

const modelFamily modelFamilies[] =
{
    { "normalModel", &modelExists<Foam::normalContactModel> },
    { "tangentialModel", &modelExists<Foam::tangentialContactModel> },
    { "rollingModel", &modelExists<Foam::rollingContactModel> },
    { "cohesionModel", &modelExists<Foam::cohesionContactModel> }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demEngine::readWalls(const dictionary& dict, const polyMesh* mesh)
{
    const dictionary* wallsDict = dict.findDict("walls");
    if (!wallsDict)
    {
        return;
    }

    const wordList names(wallsDict->toc());

    if (names.size() > maxWalls)
    {
        FatalIOErrorInFunction(*wallsDict)
            << names.size() << " walls in dictionary " << wallsDict->name()
            << "; at most " << maxWalls << " are supported (merge walls of "
            << "the same material into one triangles or patch wall)"
            << exit(FatalIOError);
    }

    walls_.setSize(names.size());
    wallMaterial_.setSize(names.size());

    forAll(names, wi)
    {
        const dictionary& wd = wallsDict->subDict(names[wi]);
        walls_.set(wi, demWall::New(names[wi], wd, mesh));
        wallMaterial_[wi] =
            materials_.typeIndex(walls_[wi].material(), wd, "material");
    }
}


Foam::scalar Foam::demEngine::defaultSkin() const
{
    scalar dMin = GREAT;
    for (label i = 0; i < materials_.size(); ++i)
    {
        if (materials_.isParticleType(i))
        {
            dMin = min(dMin, materials_.diameter(i));
        }
    }
    return dMin < GREAT ? dMin : 0;
}


void Foam::demEngine::checkTimeStep(const dictionary& dict) const
{
    const demMaterials& mat = materials_;
    const scalar v = maxImpactVelocity_;
    const scalar dt = timeStep_;

    // A table: 6 digits whatever the case's writePrecision (17 digits
    // would overflow the columns)
    const int oldPrecision = Info().precision(6);

    Info<< nl << "DEM time-step check: timeStep " << dt
        << " s, maxImpactVelocity " << v << " m/s" << nl
        << "    Hertz contact time t_H (elastic, dynamic reduced mass), "
        << "limits: error above t_H/3, warning above t_H/10" << nl
        << "    " << setw(24) << "pair" << setw(13) << "R* [m]"
        << setw(13) << "m_dyn [kg]" << setw(13) << "t_H [s]"
        << setw(13) << "t_H/dt" << setw(13) << "dmax/R*" << nl;

    scalar worstRatio = GREAT;
    word worstPair;
    scalar worstTH = 0;

    // Elastic Hertz impact: t_H = 2.9432 delta_max/v (2 int_0^1
    // dx/sqrt(1 - x^(5/2))), so the peak overlap follows from t_H without
    // the model's stiffness. Beyond a fraction of R* the Hertz law is
    // meaningless and past ~R* particles pass through each other or the
    // wall silently (bench/stability: Y = 5e6 Pa at 30 m/s), which no time
    // step cures: warn above 0.1 R*, refuse above 0.5 R*
    scalar worstOverlap = 0;
    word worstOverlapPair;

    auto row = [&](const word& name, const scalar Rstar, const scalar m,
                   const scalar tH)
    {
        const scalar overlap = v*tH/2.9432/Rstar;

        Info<< "    " << setw(24) << name << setw(13) << Rstar
            << setw(13) << m << setw(13) << tH << setw(13) << tH/dt
            << setw(13) << overlap << nl;

        if (tH/dt < worstRatio)
        {
            worstRatio = tH/dt;
            worstPair = name;
            worstTH = tH;
        }

        if (overlap > worstOverlap)
        {
            worstOverlap = overlap;
            worstOverlapPair = name;
        }

        if (overlap > 0.1 && overlap <= 0.5)
        {
            WarningIn("Foam::demEngine::checkTimeStep")
                << "Contact " << name << " at maxImpactVelocity " << v
                << " m/s reaches an elastic overlap of " << overlap
                << " R*; Hertz contact assumes small overlaps (< 0.1 R*):"
                << " a stiffer (less softened) youngsModulus or a smaller"
                << " maxImpactVelocity is advised" << endl;
        }

        if (dt > tH/10 && dt <= tH/3)
        {
            WarningIn("Foam::demEngine::checkTimeStep")
                << "DEM timeStep " << dt << " s resolves a contact of "
                << name << " with only " << tH/dt << " steps (t_H = " << tH
                << " s at " << v << " m/s); 10 or more are advised"
                << endl;
        }
    };

    // Wall materials in use
    labelList wallTypes(wallMaterial_);
    Foam::sort(wallTypes);
    wallTypes.setSize(std::unique(wallTypes.begin(), wallTypes.end())
        - wallTypes.begin());

    for (label i = 0; i < mat.size(); ++i)
    {
        if (!mat.isParticleType(i))
        {
            continue;
        }
        const scalar ri = 0.5*mat.diameter(i);
        const scalar mi = mat.primaryMass(i);

        for (label j = i; j < mat.size(); ++j)
        {
            if (!mat.isParticleType(j))
            {
                continue;
            }
            const scalar rj = 0.5*mat.diameter(j);
            const scalar mj = mat.primaryMass(j);
            const scalar Rstar = ri*rj/(ri + rj);
            const scalar mdyn = pairScaling::dynamicReducedMass
            (
                mi, mat.N(i), mj, mat.N(j)
            );
            const scalar tH =
                normal_->contactTime(mat.pair(i, j), Rstar, mdyn, v);

            row(mat.names()[i] + "-" + mat.names()[j], Rstar, mdyn, tH);

            // Theory 7.3: a parcel of N primaries approaching a carrier's
            // mass breaks the "N primaries on one carrier" picture
            const scalar Ni = mat.N(i), Nj = mat.N(j);
            if (Ni != Nj)
            {
                const scalar ratio = (Ni > Nj) ? Ni*mi/mj : Nj*mj/mi;
                if (ratio > 0.1)
                {
                    WarningInFunction
                        << "Pair " << mat.names()[i] << "-"
                        << mat.names()[j] << ": the parcel mass N m is "
                        << ratio << " of its partner's; the carrier recoil"
                        << " (theory 2.4) is no longer small (> 0.1)"
                        << endl;
                }
            }
        }

        for (const label w : wallTypes)
        {
            const scalar mdyn = pairScaling::dynamicReducedMass(mi, mat.N(i));
            const scalar tH = normal_->contactTime(mat.pair(i, w), ri, mdyn, v);
            row
            (
                mat.names()[i] + "-" + mat.names()[w] + "(wall)",
                ri,
                mdyn,
                tH
            );
        }
    }

    Info<< "    Rayleigh time T_R: warning above 0.3 T_R" << nl;
    for (label i = 0; i < mat.size(); ++i)
    {
        if (!mat.isParticleType(i))
        {
            continue;
        }
        const scalar TR = mat.rayleighTime(i);
        Info<< "    " << setw(24) << mat.names()[i] << "  T_R " << TR
            << " s, timeStep/T_R " << dt/TR << nl;

        if (dt > 0.3*TR)
        {
            WarningInFunction
                << "DEM timeStep " << dt << " s is " << dt/TR
                << " of the Rayleigh time of type " << mat.names()[i]
                << " (T_R = " << TR << " s); 0.3 or less is advised"
                << endl;
        }
    }
    Info<< endl;
    Info().precision(oldPrecision);

    if (worstOverlap > 0.5)
    {
        if (allowUnstable_)
        {
            WarningInFunction
                << "Contact " << worstOverlapPair << " reaches an elastic"
                << " overlap of " << worstOverlap << " R* at "
                << "maxImpactVelocity " << v << " m/s (limit 0.5 R*); "
                << "running anyway (allowUnstable true)" << endl;
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Contact " << worstOverlapPair << " reaches an elastic "
                << "overlap of " << worstOverlap << " R* at "
                << "timeStepCheck/maxImpactVelocity " << v << " m/s in "
                << "dictionary " << dict.name() << " (limit 0.5 R*)." << nl
                << "    Particles would pass through each other or the "
                << "walls whatever the time step: raise youngsModulus (less"
                << " softening) or lower maxImpactVelocity if the scene "
                << "cannot reach it, or set timeStepCheck "
                << "{ allowUnstable true; }"
                << exit(FatalIOError);
        }
    }

    if (worstRatio < 3)
    {
        if (allowUnstable_)
        {
            WarningInFunction
                << "DEM timeStep " << dt << " s is above the stability "
                << "limit t_H/3 = " << worstTH/3 << " s of pair "
                << worstPair << "; running anyway (allowUnstable true)"
                << endl;
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "DEM timeStep " << dt << " s in dictionary "
                << dict.name() << " is above the stability limit t_H/3 = "
                << worstTH/3 << " s of pair " << worstPair << nl
                << "    (elastic Hertz contact time t_H = " << worstTH
                << " s at maxImpactVelocity " << v << " m/s; velocity "
                << "Verlet diverges near t_H/2)" << nl
                << "Reduce timeStep to at most " << worstTH/3
                << " s, or set timeStepCheck { allowUnstable true; }"
                << exit(FatalIOError);
        }
    }
}


void Foam::demEngine::checkState(const demState& s) const
{
    scalar coarseN = -1;
    label coarseId = -1;

    forAll(s.N, i)
    {
        const scalar Ni = s.N[i];
        if (!(Ni > 0))
        {
            FatalErrorInFunction
                << "Parcel " << s.globalId[i] << " has N = " << Ni
                << "; the coarsening factor must be > 0"
                << exit(FatalError);
        }
        if (Ni > 1)
        {
            if (coarseN < 0)
            {
                coarseN = Ni;
                coarseId = s.globalId[i];
            }
            else if (Ni != coarseN)
            {
                FatalErrorInFunction
                    << "Parcels " << coarseId << " (N " << coarseN
                    << ") and " << s.globalId[i] << " (N " << Ni << ") are "
                    << "coarse-grained with different N > 1: the pair factor"
                    << " max(N_i, N_j) cannot conserve momentum between "
                    << "them (theory 2.4). Use one N for all parcels."
                    << exit(FatalError);
            }
        }
        if (s.typeId[i] < 0 || s.typeId[i] >= materials_.size())
        {
            FatalErrorInFunction
                << "Parcel " << s.globalId[i] << " has type index "
                << s.typeId[i] << "; types: " << materials_.names()
                << exit(FatalError);
        }
    }
}


void Foam::demEngine::flushHistory()
{
    if (!workingValid_)
    {
        return;
    }

    // The working arrays are the current truth for every contact they hold;
    // contacts not in them have separated (the list covers all pairs within
    // reach) so the store is rebuilt from them
    history_.clear();

    forAll(pairRow_, a)
    {
        const label idi = workingIds_[pairRow_[a]];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            if (pairHasXi_[k] && pairXi_[k] != vector::zero)
            {
                history_.set(idi, workingIds_[pairJ_[k]], pairXi_[k]);
            }
        }
    }

    forAll(wallState_, p)
    {
        for (const wallContactState& w : wallState_[p])
        {
            history_.set
            (
                workingIds_[p],
                wallPartnerKey(w.wall, w.key),
                w.xi
            );
        }
    }
}


void Foam::demEngine::prepareWalls(const scalar reach)
{
    if (reach > wallReach_)
    {
        // A little margin so a slightly larger parcel does not re-bin
        wallReach_ = 1.1*reach;
        for (demWall& w : walls_)
        {
            w.prepare(wallReach_);
        }
    }
}


void Foam::demEngine::rebuild(const demState& s)
{
    const double t0 = wallClock();

    flushHistory();

    const label n = s.size();

    scalar rMax = 0;
    for (const scalar r : s.r)
    {
        rMax = max(rMax, r);
    }
    const scalar range = cohesion_->maxRange(rMax);

    search_.build
    (
        s,
        [this](const scalar ri, const scalar rj)
        {
            return cohesion_->maxPairRange(ri, rj);
        }
    );

    // Walls must see every sphere within its radius plus cohesion range,
    // and, for the near-wall test below, the skin
    prepareWalls(rMax + range + search_.skin());

    // Rows that may reach a wall before the next rebuild, and the wall
    // elements each may reach: no row moves more than half the skin before
    // the next rebuild, so an element out of reach plus the skin now stays
    // out of reach until then
    const label nWalls = walls_.size();
    nearWall_.clear();
    wallCandStart_.setSize(n*nWalls + 1);
    wallCand_.clear();
    for (label p = 0; p < n; ++p)
    {
        const scalar rp = s.r[p];
        const scalar query = rp + cohesion_->maxRange(rp) + search_.skin();
        const label start = wallCand_.size();
        forAll(walls_, w)
        {
            wallCandStart_[p*nWalls + w] = wallCand_.size();
            walls_[w].findCandidates(s.x[p], query, wallCand_);
        }
        if (wallCand_.size() > start)
        {
            nearWall_.append(p);
        }
    }
    wallCandStart_[n*nWalls] = wallCand_.size();

    // The half list in globalId order (see pairRow_)
    const DynamicList<labelPair>& pairs = search_.pairs();
    const label np = pairs.size();
    {
        const labelUList& id = s.globalId;

        labelList byId(identity(n));
        std::sort
        (
            byId.begin(),
            byId.end(),
            [&id](const label a, const label b) { return id[a] < id[b]; }
        );

        labelList fill(n, 0);
        for (const labelPair& pr : pairs)
        {
            ++fill[pr.first()];
        }

        pairRow_.setSize(n);
        pairStart_.setSize(n + 1);
        label nRows = 0;
        label k = 0;
        for (const label i : byId)
        {
            if (fill[i])
            {
                pairRow_[nRows] = i;
                pairStart_[nRows] = k;
                ++nRows;
                const label count = fill[i];
                fill[i] = k;
                k += count;
            }
        }
        pairStart_[nRows] = k;
        pairRow_.setSize(nRows);
        pairStart_.setSize(nRows + 1);

        pairJ_.setSize(np);
        for (const labelPair& pr : pairs)
        {
            pairJ_[fill[pr.first()]++] = pr.second();
        }

        for (label a = 0; a < nRows; ++a)
        {
            std::sort
            (
                pairJ_.begin() + pairStart_[a],
                pairJ_.begin() + pairStart_[a + 1],
                [&id](const label a, const label b) { return id[a] < id[b]; }
            );
        }
    }

    // Per pair: the distance from which it cannot interact, and the working
    // history from the store. The cut-off of the global range (as before
    // per-pair ranges) is kept where it is the smaller, so that a pair at
    // the edge of the range is decided exactly as it was; the per-pair one
    // has a margin far above round-off, so it drops only pairs that are
    // certainly out of range
    pairCut2_.setSize(np);
    pairXi_.setSize(np);
    pairHasXi_.setSize(np);
    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            const label j = pairJ_[k];
            const scalar rSum = s.r[i] + s.r[j];
            const scalar pairRange = cohesion_->maxPairRange(s.r[i], s.r[j]);
            pairCut2_[k] = min
            (
                sqr(rSum + range),
                sqr((rSum + pairRange)*(1 + 1e-9))
            );
            pairXi_[k] = history_.find(s.globalId[i], s.globalId[j]);
            pairHasXi_[k] = (pairXi_[k] != vector::zero);
        }
    }

    // Wall contacts of parcels seen before keep their full state, normal
    // included: a contact moving to a neighbouring triangle right after a
    // rebuild must find its history, or results would depend on when the
    // list is rebuilt (e.g. every fluid step in parallel, never in serial)
    Map<label> oldRow;
    List<DynamicList<wallContactState>> oldState;
    if (wallState_.size() == workingIds_.size())
    {
        oldRow.resize(2*workingIds_.size());
        forAll(workingIds_, q)
        {
            oldRow.insert(workingIds_[q], q);
        }
        oldState.transfer(wallState_);
    }

    wallState_.setSize(n);
    DynamicList<label> keys;
    DynamicList<vector> xis;
    for (label p = 0; p < n; ++p)
    {
        wallState_[p].clear();

        const auto iter = oldRow.cfind(s.globalId[p]);
        if (iter.found() && iter.val() < oldState.size())
        {
            wallState_[p] = oldState[iter.val()];
            continue;
        }

        keys.clear();
        xis.clear();
        history_.history(s.globalId[p], keys, xis);
        forAll(keys, c)
        {
            if (keys[c] < 0)
            {
                const label code = -1 - keys[c];
                wallContactState w;
                w.wall = code % maxWalls;
                w.key = code/maxWalls;
                w.n = Zero;     // unknown until the next evaluation
                w.xi = xis[c];
                wallState_[p].append(w);
            }
        }
    }

    workingIds_ = s.globalId;
    workingValid_ = true;

    timeNeighbour_ += wallClock() - t0;
}


void Foam::demEngine::pairForces(const demState& s, const bool advance)
{
    const bool cohesive = cohesion_->active();
    const bool rolls = rolling_->active();
    const bool damping = normal_->tangentialDamping();
    const bool rollScaled = rolling_->scaledWithN();
    const label nOwned = s.owned();

    demContact c;
    c.wall = false;
    // A re-evaluation also takes the trial step xi + v_s dt (a new contact
    // must not start in the sticking branch with its dashpot) but keeps it
    // only when advancing
    c.dt = timeStep_;

    // A force is added to both rows as soon as it is known, in the order of
    // the half list, i.e. to each row in its partners' globalId order.
    // Pairs out of range add nothing: adding zeros would not change a sum
    // (which is never -0, starting from +0), so skipping them changes no bit
    // The partners' positions are read in no spatial order (the rows are
    // in the cloud's order): ask for them a few pairs ahead
    const label np = pairJ_.size();
    const label ahead = 16;

    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        const point xi0 = s.x[i];

        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            if (k + ahead < np)
            {
                __builtin_prefetch(&s.x[pairJ_[k + ahead]]);
            }

            const label j = pairJ_[k];

            const vector d(xi0 - s.x[j]);
            const scalar r2 = magSqr(d);

            if (r2 >= pairCut2_[k])
            {
                if (advance && pairHasXi_[k])
                {
                    pairXi_[k] = Zero;
                    pairHasXi_[k] = false;
                }
                continue;
            }

            const scalar rSum = s.r[i] + s.r[j];
            const scalar r = sqrt(r2);
            c.n = d/r;
            c.delta = rSum - r;
            c.props = &materials_.pair(s.typeId[i], s.typeId[j]);
            c.typei = s.typeId[i];
            c.typej = s.typeId[j];
            c.ri = s.r[i];
            c.rj = s.r[j];
            c.Rstar = s.r[i]*s.r[j]/rSum;
            c.mstar = s.m[i]*s.m[j]/(s.m[i] + s.m[j]);

            const scalar S = pairScaling::pair(s.N[i], s.N[j]);

            if (!c.touching())
            {
                if (advance && pairHasXi_[k])
                {
                    pairXi_[k] = Zero;
                    pairHasXi_[k] = false;
                }
                if (cohesive && -c.delta < cohesion_->range(c))
                {
                    const vector F((-S*cohesion_->force(c))*c.n);
                    fContact_[i] += F;
                    fContact_[j] -= F;
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

            // Normal, cohesion, tangential, rolling (theory 1.6)
            scalar fElastic = 0;
            const scalar fn = normal_->force(c, fElastic);
            vector F(fn*c.n);

            if (cohesive)
            {
                F -= cohesion_->force(c)*c.n;
            }

            vector xi(pairXi_[k]);
            const vector Ft(tangential_->force(c, fn, damping, xi));
            if (advance)
            {
                pairXi_[k] = xi;
                pairHasXi_[k] = true;
            }
            F += Ft;

            const vector Fk(S*F);
            vector Ti(S*(-c.ci*(c.n ^ Ft)));
            vector Tj(S*(-c.cj*(c.n ^ Ft)));

            if (rolls)
            {
                const vector M(rolling_->torque(c, fElastic));
                const scalar Sr = pairScaling::torqueFactor(S, rollScaled);
                Ti += Sr*M;
                Tj -= Sr*M;
            }

            fContact_[i] += Fk;
            tContact_[i] += Ti;
            fContact_[j] -= Fk;
            tContact_[j] += Tj;

            // Each pair counted once over all processors: where the row of
            // the smaller globalId (i) is owned
            if (i < nOwned)
            {
                ++diag_.nPairContacts;
                diag_.record
                (
                    c.delta/c.Rstar, -c.vn, s.globalId[i], s.globalId[j]
                );
            }
        }
    }
}


void Foam::demEngine::wallForces
(
    const demState& s,
    const label p,
    const bool advance
)
{
    wallContrib_.clear();
    wallNew_.clear();

    if (walls_.empty())
    {
        return;
    }

    const scalar rp = s.r[p];
    const scalar reach = rp + cohesion_->maxRange(rp);
    const label nWalls = walls_.size();

    DynamicList<wallContactState>& old = wallState_[p];

    // The contacts of all walls first: most rows near a wall touch none
    // and need nothing more
    wallBuf_.clear();
    wallBufWall_.clear();
    forAll(walls_, w)
    {
        const label first = wallCandStart_[p*nWalls + w];
        const label nCand = wallCandStart_[p*nWalls + w + 1] - first;
        if (nCand)
        {
            walls_[w].findContacts
            (
                s.x[p],
                reach,
                SubList<label>(wallCand_, nCand, first),
                wallBuf_
            );
            while (wallBufWall_.size() < wallBuf_.size())
            {
                wallBufWall_.append(w);
            }
        }
    }

    if (wallBuf_.empty())
    {
        if (advance)
        {
            old.clear();
        }
        return;
    }

    const bool cohesive = cohesion_->active();
    const bool rolls = rolling_->active();
    const bool damping = normal_->tangentialDamping();
    const bool rollScaled = rolling_->scaledWithN();

    const scalar S = pairScaling::wall(s.N[p]);

    demContact c;
    c.wall = true;
    // A re-evaluation also takes the trial step xi + v_s dt (a new contact
    // must not start in the sticking branch with its dashpot) but keeps it
    // only when advancing
    c.dt = timeStep_;
    c.Rstar = rp;
    c.mstar = s.m[p];
    c.typei = s.typeId[p];
    c.ri = rp;
    c.rj = 0;
    c.cj = 0;
    c.omegaRel = s.omega[p];

    forAll(wallBuf_, b)
    {
        const demWallContact& wc = wallBuf_[b];
        const label w = wallBufWall_[b];

        c.n = wc.n;
        c.delta = rp - wc.distance;
        c.props = &materials_.pair(s.typeId[p], wallMaterial_[w]);
        c.typej = wallMaterial_[w];

        wallContribution contrib;
        contrib.partnerKey = wallPartnerKey(w, wc.key);
        contrib.f = Zero;
        contrib.t = Zero;

        if (!c.touching())
        {
            if (cohesive && -c.delta < cohesion_->range(c))
            {
                contrib.f = (-S*cohesion_->force(c))*c.n;
                wallContrib_.append(contrib);
            }
            continue;
        }

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
                    for (const wallContactState& nw : wallNew_)
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

        scalar fElastic = 0;
        const scalar fn = normal_->force(c, fElastic);
        vector F(fn*c.n);
        if (cohesive)
        {
            F -= cohesion_->force(c)*c.n;
        }

        const vector Ft(tangential_->force(c, fn, damping, xi));
        F += Ft;

        contrib.f = S*F;
        contrib.t = S*(-c.ci*(c.n ^ Ft));

        if (rolls)
        {
            contrib.t +=
                pairScaling::torqueFactor(S, rollScaled)
               *rolling_->torque(c, fElastic);
        }

        wallContrib_.append(contrib);

        if (advance)
        {
            wallContactState st;
            st.wall = w;
            st.key = wc.key;
            st.n = c.n;
            st.xi = xi;
            wallNew_.append(st);
        }

        if (p < s.owned())
        {
            ++diag_.nWallContacts;
            diag_.record(c.delta/rp, -c.vn, s.globalId[p], -1 - w);
        }
    }

    if (advance)
    {
        old = wallNew_;
    }

    std::sort
    (
        wallContrib_.begin(),
        wallContrib_.end(),
        [](const wallContribution& a, const wallContribution& b)
        {
            return a.partnerKey < b.partnerKey;
        }
    );
}


void Foam::demEngine::evaluate
(
    demState& s,
    const bool advance,
    const label checkedRows
)
{
    const label n = s.size();

    double t0 = wallClock();

    if (!workingValid_ || search_.needsRebuild(s, checkedRows))
    {
        rebuild(s);
    }
    else
    {
        timeNeighbour_ += wallClock() - t0;
    }

    diag_.nPairContacts = 0;
    diag_.nWallContacts = 0;
    diag_.maxOverlapRatio = 0;

    t0 = wallClock();

    fContact_.setSize(n);
    tContact_.setSize(n);
    fContact_ = Zero;
    tContact_ = Zero;

    pairForces(s, advance);

    double t1 = wallClock();
    timePair_ += t1 - t0;

    for (const label p : nearWall_)
    {
        wallForces(s, p, advance);
        for (const wallContribution& wc : wallContrib_)
        {
            fContact_[p] += wc.f;
            tContact_[p] += wc.t;
        }
    }

    timeWall_ += wallClock() - t1;
}


void Foam::demEngine::totalForces(demState& s) const
{
    forAll(s.x, p)
    {
        s.f[p] = fContact_[p] + (s.N[p]*s.m[p])*g_ + s.fExt[p];
        s.torque[p] = tContact_[p];
    }
}


bool Foam::demEngine::reuseCache(const demState& s)
{
    const label n = s.size();

    if (!cacheValid_ || n != cacheX_.size())
    {
        return false;
    }

    // Rows in the same order (the usual case): compare directly
    bool sameOrder = true;
    forAll(cacheX_, p)
    {
        if (s.globalId[p] != cacheId_[p])
        {
            sameOrder = false;
            break;
        }
    }

    labelList from(identity(n));
    if (!sameOrder)
    {
        // The cloud reordered its parcels: match them by globalId
        Map<label> rowOf(2*n);
        forAll(cacheId_, p)
        {
            rowOf.insert(cacheId_[p], p);
        }
        forAll(from, p)
        {
            const auto iter = rowOf.cfind(s.globalId[p]);
            if (!iter.found())
            {
                return false;
            }
            from[p] = iter.val();
        }
    }

    forAll(from, p)
    {
        const label q = from[p];
        if
        (
            s.x[p] != cacheX_[q]
         || s.v[p] != cacheV_[q]
         || s.omega[p] != cacheOmega_[q]
        )
        {
            return false;
        }
    }

    if (!sameOrder)
    {
        const List<vector> f(fContact_), t(tContact_);
        forAll(from, p)
        {
            fContact_[p] = f[from[p]];
            tContact_[p] = t[from[p]];
        }
    }

    return true;
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::label Foam::demEngine::warnUnknownKeys(const dictionary& dict)
{
    label nWarnings = 0;

    // The selected models' Coeffs are read by the models themselves
    wordList known(keys);
    for (const modelFamily& f : modelFamilies)
    {
        const word model(dict.getOrDefault<word>(f.key, word::null));
        if (model.size() && !known.found(model + "Coeffs"))
        {
            known.append(model + "Coeffs");
        }
    }

    // The Coeffs of a model that exists but is not selected is ignored
    // (usually a model switched off, e.g. rollingModel none with cdtCoeffs
    // left in place): say so, naming the model that is selected, rather
    // than calling it unknown
    const word suffix("Coeffs");
    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if
        (
            key.isPattern()
         || key.size() <= suffix.size()
         || !key.ends_with(suffix)
         || known.found(key)
        )
        {
            continue;
        }

        const word model(key.substr(0, key.size() - suffix.size()));
        for (const modelFamily& f : modelFamilies)
        {
            if (f.exists(model))
            {
                IOWarningInFunction(dict)
                    << "Dictionary '" << key.c_str() << "' in dictionary "
                    << dict.name().c_str() << " is not used: " << f.key
                    << " is "
                    << dict.getOrDefault<word>(f.key, word::null).c_str()
                    << " (" << key.c_str() << " is read only with "
                    << f.key << " " << model.c_str() << ")" << endl;

                known.append(key);
                ++nWarnings;
                break;
            }
        }
    }

    return nWarnings + dictKeys::warnUnknown(dict, known);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demEngine::demEngine(const dictionary& dict, const polyMesh* mesh)
:
    timeStep_(dict.get<scalar>("timeStep")),
    materials_(dict),
    normal_(normalContactModel::New(dict)),
    tangential_(tangentialContactModel::New(dict)),
    rolling_(rollingContactModel::New(dict)),
    cohesion_(cohesionContactModel::New(dict)),
    walls_(),
    wallMaterial_(),
    search_(0),
    maxImpactVelocity_(0),
    startOverlapWarn_(0.01),
    startOverlapRefuse_(0.1),
    runOverlapWarn_(0.1),
    runOverlapRefuse_(0.5),
    allowUnstable_(false),
    g_(Zero),
    time_(0),
    history_(),
    workingValid_(false),
    wallReach_(0),
    nearWall_(),
    cacheValid_(false),
    diag_(),
    timePair_(0),
    timeWall_(0),
    timeNeighbour_(0),
    timeIntegrate_(0),
    nSteps_(0),
    nParticleSteps_(0),
    halo_(nullptr)
{
    if (!(timeStep_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'timeStep' = " << timeStep_ << " in dictionary "
            << dict.name() << " must be > 0" << exit(FatalIOError);
    }

    readWalls(dict, mesh);

    const dictionary nsDict(dict.subOrEmptyDict("neighbourSearch"));
    dictKeys::warnUnknown(nsDict, {"skin"});
    const scalar skin = nsDict.getOrDefault<scalar>("skin", defaultSkin());
    if (!(skin > 0))
    {
        FatalIOErrorInFunction(dict)
            << "The neighbour-search skin must be > 0 (got " << skin
            << "); set neighbourSearch { skin ...; } in dictionary "
            << dict.name() << exit(FatalIOError);
    }
    search_ = neighbourSearch(skin);

    const dictionary& tsDict = dict.subDict("timeStepCheck");
    dictKeys::warnUnknown(tsDict, {"maxImpactVelocity", "allowUnstable"});
    maxImpactVelocity_ = tsDict.get<scalar>("maxImpactVelocity");
    if (!(maxImpactVelocity_ > 0))
    {
        FatalIOErrorInFunction(tsDict)
            << "Entry 'maxImpactVelocity' = " << maxImpactVelocity_
            << " in dictionary " << tsDict.name() << " must be > 0"
            << exit(FatalIOError);
    }
    allowUnstable_ = tsDict.getOrDefault<bool>("allowUnstable", false);

    const dictionary soDict(dict.subOrEmptyDict("startOverlap"));
    dictKeys::warnUnknown(soDict, {"warn", "refuse"});
    startOverlapWarn_ = soDict.getOrDefault<scalar>("warn", startOverlapWarn_);
    startOverlapRefuse_ =
        soDict.getOrDefault<scalar>("refuse", startOverlapRefuse_);
    if (!(startOverlapWarn_ > 0) || !(startOverlapRefuse_ >= startOverlapWarn_))
    {
        FatalIOErrorInFunction(dict)
            << "startOverlap { warn " << startOverlapWarn_ << "; refuse "
            << startOverlapRefuse_ << "; } in dictionary " << dict.name()
            << ": need 0 < warn <= refuse (overlap / R*; defaults 0.01 and"
            << " 0.1)" << exit(FatalIOError);
    }

    // While running: Hertz contact holds for small overlaps (about 0.1 R*,
    // where the start-up check also warns); at 0.5 R* the contact is far
    // outside it and a little more takes a parcel through its partner
    const dictionary ocDict(dict.subOrEmptyDict("overlapCheck"));
    dictKeys::warnUnknown(ocDict, {"warn", "refuse"});
    runOverlapWarn_ = ocDict.getOrDefault<scalar>("warn", runOverlapWarn_);
    runOverlapRefuse_ =
        ocDict.getOrDefault<scalar>("refuse", runOverlapRefuse_);
    if (!(runOverlapWarn_ > 0) || !(runOverlapRefuse_ >= runOverlapWarn_))
    {
        FatalIOErrorInFunction(dict)
            << "overlapCheck { warn " << runOverlapWarn_ << "; refuse "
            << runOverlapRefuse_ << "; } in dictionary " << dict.name()
            << ": need 0 < warn <= refuse (overlap / R*; defaults 0.1 and"
            << " 0.5)" << exit(FatalIOError);
    }

    Info<< "DEM engine: " << materials_.size() << " types "
        << materials_.names() << ", " << walls_.size() << " walls, skin "
        << skin << " m" << endl;

    checkTimeStep(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demEngine::evolve
(
    demState& s,
    const scalar Dt,
    const vector& g,
    demObserver* obs
)
{
    const scalar ratio = Dt/timeStep_;
    const label nSub = label(ratio + 0.5);

    if (nSub < 0 || mag(ratio - nSub) > 1e-6)
    {
        FatalErrorInFunction
            << "The fluid time step " << Dt << " s is not an integer "
            << "multiple of the DEM timeStep " << timeStep_ << " s (ratio "
            << ratio << ")" << exit(FatalError);
    }
    if (nSub == 0)
    {
        return;
    }

    checkState(s);

    // Only owned rows are integrated; ghosts (halo copies) are refreshed
    // by the halo from their owners
    const label n = s.owned();
    const scalar dt = timeStep_;
    const scalar t0 = time_;

    g_ = g;

    // Forces of the starting state: those of the last sub-step if the cloud
    // has not touched the state since (so splitting a run into evolve calls
    // changes nothing), else a re-evaluation that leaves the history as is
    if (reuseCache(s))
    {
        totalForces(s);
    }
    else if (s.contactForcesValid)
    {
        // Given by the caller (restart, or parcels handed back unchanged)
        fContact_ = s.fContact;
        tContact_ = s.tContact;
        totalForces(s);
    }
    else
    {
        evaluate(s, false);
        totalForces(s);
    }

    // Per owned row, the half-step factors dt/(2M), dt/(2I), evaluated once
    // per evolve instead of twice per sub-step (two divisions each), by the
    // same expressions so the update is unchanged to the bit
    double tc = wallClock();

    halfStepV_.setSize(n);
    halfStepOmega_.setSize(n);
    for (label p = 0; p < n; ++p)
    {
        const scalar M = s.N[p]*s.m[p];
        const scalar I = 0.4*M*sqr(s.r[p]);
        halfStepV_[p] = 0.5*dt/M;
        halfStepOmega_[p] = 0.5*dt/I;
    }

    timeIntegrate_ += wallClock() - tc;

    for (label step = 0; step < nSub; ++step)
    {
        tc = wallClock();

        // Values just stored are not read back (a store read back by a
        // wider load stalls the pipeline).
        // After the first sub-step (which checks everything: the cloud may
        // have changed the rows) the owned rows are the particles of the
        // neighbour list's build, and their move since the build is
        // measured here, saving a pass over the rows in needsRebuild
        const List<point>& x0 = search_.x0();
        const bool track =
            step > 0 && search_.valid() && x0.size() == s.size();
        scalar maxMove2 = 0;

        if (track)
        {
            for (label p = 0; p < n; ++p)
            {
                const vector v(s.v[p] + halfStepV_[p]*s.f[p]);
                s.v[p] = v;
                s.omega[p] += halfStepOmega_[p]*s.torque[p];
                const point x(s.x[p] + dt*v);
                s.x[p] = x;
                maxMove2 = max(maxMove2, magSqr(x - x0[p]));
            }
        }
        else
        {
            for (label p = 0; p < n; ++p)
            {
                const vector v(s.v[p] + halfStepV_[p]*s.f[p]);
                s.v[p] = v;
                s.omega[p] += halfStepOmega_[p]*s.torque[p];
                s.x[p] += dt*v;
            }
        }

        timeIntegrate_ += wallClock() - tc;

        if (halo_)
        {
            halo_->update(s);
        }

        // As neighbourSearch::needsRebuild decides
        const bool ownedChecked =
            track && !(maxMove2 > sqr(0.5*search_.skin()));

        evaluate(s, true, ownedChecked ? n : 0);

        tc = wallClock();

        // Total forces (as totalForces) and the second half kick in one
        // pass over the rows
        scalar Ek = 0, Er = 0;
        for (label p = 0; p < n; ++p)
        {
            const scalar M = s.N[p]*s.m[p];
            const vector f(fContact_[p] + M*g_ + s.fExt[p]);
            const vector t(tContact_[p]);
            s.f[p] = f;
            s.torque[p] = t;
            const vector v(s.v[p] + halfStepV_[p]*f);
            const vector omega(s.omega[p] + halfStepOmega_[p]*t);
            s.v[p] = v;
            s.omega[p] = omega;
            Ek += 0.5*M*magSqr(v);
            Er += 0.5*(0.4*M*sqr(s.r[p]))*magSqr(omega);
        }
        for (label p = n; p < s.size(); ++p)
        {
            s.f[p] = fContact_[p] + (s.N[p]*s.m[p])*g_ + s.fExt[p];
            s.torque[p] = tContact_[p];
        }

        timeIntegrate_ += wallClock() - tc;

        time_ = t0 + (step + 1)*dt;
        diag_.time = time_;
        diag_.kineticEnergy = Ek;
        diag_.rotationalEnergy = Er;
        ++nSteps_;
        nParticleSteps_ += n;

        if (obs)
        {
            obs->subStep(time_, s);
        }
    }

    // Travel per step in radii: once per fluid step (the contacts' checks
    // cannot see a parcel that jumps a wall or a partner between steps)
    for (label p = 0; p < n; ++p)
    {
        const scalar travel = mag(s.v[p])*dt/s.r[p];
        if (travel > diag_.stepMaxTravel)
        {
            diag_.stepMaxTravel = travel;
            diag_.travelId = s.globalId[p];
        }
    }

    // A non-finite state (only reachable with FOAM_SIGFPE off) must not be
    // written: the energies of the last sub-step sum every owned velocity
    if (!std::isfinite(diag_.kineticEnergy + diag_.rotationalEnergy))
    {
        for (label p = 0; p < n; ++p)
        {
            if
            (
                !std::isfinite(magSqr(s.x[p]))
             || !std::isfinite(magSqr(s.v[p]))
             || !std::isfinite(magSqr(s.omega[p]))
            )
            {
                FatalErrorInFunction
                    << "Parcel " << s.globalId[p] << " has a non-finite"
                    << " state at DEM time " << time_ << ": position "
                    << s.x[p] << ", velocity " << s.v[p] << ", spin "
                    << s.omega[p] << nl << "    Stopped before it is"
                    << " written; the last written time is intact. Look at"
                    << " this parcel's contacts and forces (trace"
                    << " { parcels (" << s.globalId[p] << "); })"
                    << exit(FatalError);
            }
        }
    }

    flushHistory();

    s.fContact = fContact_;
    s.tContact = tContact_;
    s.contactForcesValid = true;

    cacheId_ = s.globalId;
    cacheX_ = s.x;
    cacheV_ = s.v;
    cacheOmega_ = s.omega;
    cacheValid_ = true;
}


Foam::scalar Foam::demEngine::interactionReach(const scalar rMax) const
{
    return 2*rMax + cohesion_->maxRange(rMax) + search_.skin();
}


void Foam::demEngine::evaluateForces(demState& s)
{
    checkState(s);
    evaluate(s, true);
    totalForces(s);
    cacheValid_ = false;
}


void Foam::demEngine::history
(
    const label globalId,
    DynamicList<label>& partnerKeys,
    DynamicList<vector>& xi
) const
{
    history_.history(globalId, partnerKeys, xi);
}


void Foam::demEngine::setHistory
(
    const label globalId,
    const labelUList& partnerKeys,
    const UList<vector>& xi
)
{
    // Bring the store up to date before editing it; the working arrays are
    // reloaded from it at the next evaluation
    flushHistory();
    workingValid_ = false;
    cacheValid_ = false;
    search_.clear();

    history_.setHistory(globalId, partnerKeys, xi);
}


void Foam::demEngine::writePerformance(Ostream& os) const
{
    const scalar total =
        timePair_ + timeWall_ + timeNeighbour_ + timeIntegrate_;

    auto pct = [&](const scalar t)
    {
        return total > 0 ? 100*t/total : 0;
    };

    os  << "DEM performance: " << nSteps_ << " steps, "
        << (total > 0 ? nParticleSteps_/total : 0) << " particle-steps/s"
        << nl
        << "    pair " << timePair_ << " s (" << pct(timePair_) << " %), "
        << "wall " << timeWall_ << " s (" << pct(timeWall_) << " %), "
        << "neighbour " << timeNeighbour_ << " s (" << pct(timeNeighbour_)
        << " %, " << search_.nBuilds() << " builds), "
        << "integrate " << timeIntegrate_ << " s ("
        << pct(timeIntegrate_) << " %)" << endl;
}


// ************************************************************************* //
