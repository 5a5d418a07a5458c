/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "DPICloud.H"
#include "cloudRecord.H"
#include "restartCheck.H"
#include "PstreamCombineReduceOps.H"
#include "clockTime.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::DPICloud<CloudType>::readState()
{
    const dictionary dpiDict
    (
        this->outputProperties().subOrEmptyDict("dpiCloud")
    );

    nextGlobalId_ = dpiDict.lookupOrDefault<label>("nextGlobalId", 0);

    const label nParcels = returnReduce(this->size(), sumOp<label>());
    const dictionary& demDict = this->particleProperties().subDict("dem");
    cloudRecord::checkState
    (
        this->outputProperties(), demDict, this->db().time(), this->name(),
        nParcels
    );

    if (nParcels)
    {
        restartCheck::checkCloud
        (
            *this, dpiDict, demDict, engine().materials(),
            engine().walls().size(), this->outputProperties()
        );
    }

    // Parcels read from a restart carry their ids: never reissue one
    label maxId = -1;
    for (const parcelType& p : *this)
    {
        maxId = max(maxId, p.globalId());
    }
    reduce(maxId, maxOp<label>());
    nextGlobalId_ = max(nextGlobalId_, maxId + 1);

    escapes_.read
    (
        Pstream::master() ? dpiDict.subOrEmptyDict("escaped") : dictionary()
    );

    // The counters live on the master (escapeRecord::read)
    cloudRecord::checkCloudPresent
    (
        this->outputProperties(), this->particleProperties(),
        this->db().time(), this->name(), nParcels, nextGlobalId_,
        escapes_.nGone(), !models_->injectors().empty()
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::storeCounters()
{
    dictionary dpiDict;
    dpiDict.add("nextGlobalId", nextGlobalId_);

    dpiDict.add
    (
        "models",
        cloudRecord::models(this->particleProperties().subDict("dem"))
    );

    // The type table a restart checks the parcels against (restartCheck)
    if (models_.valid())
    {
        labelList typeIds(this->size());
        scalarList ds(this->size());
        label i = 0;
        for (const parcelType& p : *this)
        {
            typeIds[i] = p.typeId();
            ds[i] = p.d();
            ++i;
        }
        restartCheck::writeTypes(dpiDict, engine().materials(), typeIds, ds);
    }

    // Global sums, the same on every processor (readState gives them back
    // to the master only, so a restart on any decomposition counts once)
    dpiDict.add("escaped", escapes_.totals());

    this->outputProperties().set("dpiCloud", dpiDict);
}


template<class CloudType>
Foam::label Foam::DPICloud<CloudType>::inject
(
    const scalar t0,
    const scalar t1
)
{
    // The injection's own time in the log: the set-up figure of a run
    // holds it among the mesh, the fields and the first fluid step
    const clockTime timer;

    DynamicList<injectionSpec> specs;
    labelList owner, cell, typeIds;
    if (!models_->injectors().due(t0, t1, specs, owner, cell, typeIds))
    {
        return 0;
    }

    const demMaterials& mat = engine().materials();
    forAll(specs, i)
    {
        const injectionSpec& s = specs[i];

        // Same on every processor: ids follow the list order
        const label gid = nextGlobalId_ + i;

        if (owner[i] != Pstream::myProcNo())
        {
            continue;
        }

        const label typei = typeIds[i];

        parcelType* pPtr = new parcelType(this->mesh(), s.position, cell[i]);
        parcelType& p = *pPtr;

        p.typeId() = typei;
        // The injectors give every parcel its diameter (dpiInjectors
        // draws those of polydisperse types); the type's median otherwise
        p.d() = (s.d > 0 ? s.d : mat.size(typei).numberMedian());
        p.dTarget() = p.d();
        p.rho() = mat.density(typei);
        p.N() = mat.N(typei);
        p.U() = s.U;
        p.omega() = s.omega;
        p.xDEM() = s.position;
        p.globalId() = gid;
        p.agglomerateId() = gid;

        this->addParticle(pPtr);
    }

    nextGlobalId_ += specs.size();

    Info<< "    Injected " << specs.size() << " parcels in "
        << timer.elapsedTime() << " s (wall-clock on the master)" << endl;

    return specs.size();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::DPICloud<CloudType>::DPICloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(cloudName, rho, U, mu, g, false),
    escapes_(this->mesh().boundaryMesh())
{
    if (this->solution().active())
    {
        models_.reset
        (
            new dpiCloudModels
            (
                this->particleProperties(), this->name(), this->mesh(),
                this->U(), this->rho(), this->mu()
            )
        );

        if (readFields)
        {
            cloudRecord::readFields
            (
                this->db().time(), this->name(),
                [this]() { parcelType::readFields(*this); }
            );
            this->deleteLostParticles();
        }

        readState();
    }
}


template<class CloudType>
Foam::DPICloud<CloudType>::DPICloud
(
    DPICloud<CloudType>& c,
    const word& name
)
:
    CloudType(c, name),
    nextGlobalId_(c.nextGlobalId_),
    escapes_(c.escapes_)
{}


template<class CloudType>
Foam::DPICloud<CloudType>::DPICloud
(
    const fvMesh& mesh,
    const word& name,
    const DPICloud<CloudType>& c
)
:
    CloudType(mesh, name, c),
    nextGlobalId_(c.nextGlobalId_),
    escapes_(this->mesh().boundaryMesh())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::DPICloud<CloudType>::nPrimaries(const label typeId) const
{
    scalar n = 0;
    for (const parcelType& p : *this)
    {
        if (p.typeId() == typeId)
        {
            n += p.N();
        }
    }
    return returnReduce(n, sumOp<scalar>());
}


// dpiCloudInterface
template<class CloudType>
void Foam::DPICloud<CloudType>::samples(parcelSamples& s) const
{
    const label n = this->size();
    s.setSize(n);

    label i = 0;
    for (const parcelType& p : *this)
    {
        s.position[i] = p.xDEM();
        s.N[i] = p.N();
        s.api[i] = models_.valid() && engine().materials().api(p.typeId());
        s.globalId[i] = p.globalId();
        s.agglomerateId[i] = p.agglomerateId();
        s.d[i] = p.d();
        s.rho[i] = p.rho();
        s.cell[i] = p.cell();
        ++i;
    }
}


// Void fraction hook
template<class CloudType>
const Foam::tmp<Foam::volScalarField>
Foam::DPICloud<CloudType>::theta() const
{
    if (models_.valid() && fluidCoupling().voidFraction())
    {
        return fluidCoupling().voidFraction()->theta(*this);
    }
    return CloudType::theta();
}


template<class CloudType>
void Foam::DPICloud<CloudType>::recordEscapedParcel
(
    const parcelType& p,
    const polyPatch& pp
)
{
    // Its agglomerate as labelled at the end of this fluid step's DEM
    // sub-steps, the state the move carries out
    const agglomerateTracker::composition& c = escapeComposition_;
    const label id = p.agglomerateId();

    escapedParcel e;
    e.patchi = pp.index();
    e.N = p.N();
    e.api = engine().materials().api(p.typeId());
    e.d = p.d();
    e.rho = p.rho();
    e.agglomerateParcels = c.parcels.lookup(id, 1);
    e.agglomerateVolume = c.volume.lookup(id, 0);
    e.agglomerateMass = c.mass.lookup(id, 0);
    e.onCarrier = c.carriers.lookup(id, 0) > 0;
    escapedThisStep_.append(e);

    escapes_.escaped
    (
        e.patchi, e.N, e.api, e.api && e.agglomerateParcels == 1
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::recordLostParcel
(
    const parcelType& p,
    const polyPatch& pp
)
{
    escapes_.lost(pp.index());

    // Which DEM wall, if any, lies where the parcel crossed the patch (its
    // mesh position, on the face): a patch wall listed in dem/walls, or an
    // STL wall over it. With one there the patch is a DEM wall, and the
    // parcel's centre got on or past it: a wall pushes a sphere away from
    // the side its centre is on, so a centre on the wall (a start position
    // there, a start overlap let through by dem/startOverlap/refuse) or
    // carried past it in one step is pushed out, and OpenFOAM's tracking
    // loses it. Only with none is "list the patch" the advice (was said
    // in both cases)
    word wallName;
    if (models_.valid())
    {
        DynamicList<demWallContact> contacts;
        for (const demWall& w : engine().walls())
        {
            contacts.clear();
            w.findContacts(p.position(), 0.5*p.d(), contacts);
            if (contacts.size())
            {
                wallName = w.name();
                break;
            }
        }
    }

    if (wallName.size())
    {
        WarningInFunction
            << "Parcel " << p.globalId() << " crossed wall patch "
            << pp.name() << ", DEM wall " << wallName << " (DEM position "
            << p.xDEM() << "): its centre got on or beyond the wall, and a"
            << " wall pushes a parcel to the side its centre is on, here out"
            << " of the mesh; removed." << nl
            << "    Start parcels with their centres inside the device"
            << " (dem/startOverlap/refuse lets overlaps through, not"
            << " centres on a wall), and keep the DEM step below the time"
            << " a parcel takes to cross its radius" << endl;
    }
    else
    {
        WarningInFunction
            << "Parcel " << p.globalId() << " passed through wall patch "
            << pp.name() << " (DEM position " << p.xDEM() << "), where no"
            << " DEM wall lies; removed. List the patch in dem/walls (type"
            << " patch), or cover it with a surface wall" << endl;
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::storeState()
{
    cloudCopyPtr_.reset
    (
        static_cast<DPICloud<CloudType>*>
        (
            clone(this->name() + "Copy").ptr()
        )
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::restoreState()
{
    this->cloudReset(cloudCopyPtr_());
    cloudCopyPtr_.clear();
}


template<class CloudType>
void Foam::DPICloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        typename parcelType::trackingData td(*this);
        this->solve(*this, td);
    }
}


template<class CloudType>
Foam::word Foam::DPICloud<CloudType>::startCheckDue(const label nInjected)
{
    // The start (or restart) and every injection: no parcel inside another
    // or a wall, no parcel without size (a collective decision, on the DEM
    // rows with their halo)
    if (!nInjected && startChecked_)
    {
        return word::null;
    }
    const word when(startChecked_ ? "injected" : "at the start");
    startChecked_ = true;

    // A traced id no parcel carries would trace nothing, silently
    if (models_->trace())
    {
        labelList ids(this->size());
        label i = 0;
        for (const parcelType& p : *this)
        {
            ids[i++] = p.globalId();
        }
        models_->trace()->warnAbsent
        (
            ids, nextGlobalId_, this->db().time().timeName()
        );
    }
    return when;
}


template<class CloudType>
Foam::demObserver* Foam::DPICloud<CloudType>::stepObserver(const scalar t0)
{
    demTrace* trace = models_->trace();
    if (!observer_ && trace)
    {
        trace->beginStep(t0, engine().timeStep());
        return trace;
    }
    return observer_;
}


template<class CloudType>
void Foam::DPICloud<CloudType>::subSteps
(
    const scalar Dt,
    const vector& g,
    demObserver* obs,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut
)
{
    demDomain& domain = models_->domain();
    dpiFluidCoupling& coupling = models_->coupling();
    demState& rows = domain.rows();
    if (!coupling.subStepForces())
    {
        engine().evolve(rows, Dt, g, obs);
        return;
    }

    // One engine call for the fluid step; the hook sets the forces before
    // every sub-step
    autoPtr<dpiSubStepForces> forces
    (
        coupling.newSubStepForces
        (
            rows.owned(), domain.vectorColumns(), domain.scalarColumns(),
            engine().timeStep(), engine().nSubSteps(Dt)
        )
    );
    engine().evolve(rows, Dt, g, obs, forces.get());
    coupling.subStepResults(forces(), vecOut, scaOut);
}


template<class CloudType>
void Foam::DPICloud<CloudType>::composeEscapes()
{
    const label n = this->size();
    labelList ids(n);
    scalarList d(n), rho(n);
    boolList carrier(n);
    const demMaterials& mat = engine().materials();
    label i = 0;
    for (const parcelType& p : *this)
    {
        ids[i] = p.agglomerateId();
        d[i] = p.d();
        rho[i] = p.rho();
        carrier[i] = !mat.api(p.typeId());
        ++i;
    }
    escapeComposition_ = agglomerateTracker::compose(ids, d, rho, carrier);
    escapedThisStep_.clear();
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DPICloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    const scalar Dt = this->db().time().deltaTValue();
    const scalar t1 = this->db().time().value();
    const vector g(this->g().value());

    // The parcels as the mesh rows, in list order
    const label nInjected = inject(t1 - Dt, t1);
    demEngine& engine = this->engine();
    demDomain& domain = models_->domain();
    dpiFluidCoupling& coupling = models_->coupling();
    demState& state = rows_.state();
    rows_.copy(*this, engine, domain, nInjected == 0);
    if (!domain.ordersRows())
    {
        rows_.order(*this, engine);
    }
    const word checkWhen(startCheckDue(nInjected));
    demObserver* obs = stepObserver(t1 - Dt);

    // The run-time check (demEngine::checkStep) sees the whole fluid step
    engine.resetStepDiagnostics();

    // The gas at the parcels: held forces, or the states the forces of
    // every sub-step start from
    List<vectorField> vecIn, vecOut, vecBack;
    List<scalarField> scaIn, scaOut, scaBack;
    coupling.startFluidStep(*this, state, Dt, vecIn, scaIn);

    // The rows to where the DEM runs, the start check there, the
    // sub-steps, the agglomerates labelled, every row back to its parcel
    scalar range = 0, margin = 0;
    if (domain.halo())
    {
        engine.haloReach(state, Dt, range, margin);
    }
    rows_.begin(domain, vecIn, scaIn, range, margin);
    if (checkWhen.size())
    {
        engine.checkStartState(domain.rows(), checkWhen);
    }
    subSteps(Dt, g, obs, vecOut, scaOut);
    models_->agglomerates().update
    (
        domain.rows(), engine.materials(), domain.agglomerateIds(),
        domain.halo()
    );
    rows_.end(*this, domain, vecOut, scaOut, vecBack, scaBack);
    coupling.finishFluidStep(*this, vecBack, scaBack, Dt);

    models_->agglomerates().write(t1);
    models_->reports().write
    (
        domain, t1, returnReduce(this->size(), sumOp<label>())
    );
    engine.checkStep(this->db().time().timeName());
    composeEscapes();

    // Relocate every parcel to its DEM position: one tracking pass, which
    // also hands parcels over to neighbouring processors
    CloudType::move(cloud, td, Dt);

    storeCounters();
}


template<class CloudType>
void Foam::DPICloud<CloudType>::info()
{
    CloudType::info();

    const demMaterials& mat = engine().materials();
    forAll(mat.names(), typei)
    {
        if (!mat.isParticleType(typei))
        {
            continue;
        }
        Info<< "    Primaries of type " << mat.names()[typei]
            << " = " << nPrimaries(typei) << nl;
    }

    const agglomerateTracker::statistics& ag = models_->agglomerates().stats();
    Info<< "    Agglomerates                    = " << ag.nAgglomerates
        << nl
        << "    API primaries: attached to carriers " << ag.attachedAPIPrimaries
        << ", detached " << ag.apiPrimaries - ag.attachedAPIPrimaries
        << " (singlets " << ag.singletAPIPrimaries << ")" << nl;

    // The global per-patch totals stored by this step's motion
    escapeRecord::report
    (
        Info,
        this->outputProperties().subDict("dpiCloud").subDict("escaped")
    );
}


// ************************************************************************* //
