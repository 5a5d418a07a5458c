/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "DPICloud.H"
#include "meshDomain.H"
#include "demPartition.H"
#include "cloudRecord.H"
#include "restartCheck.H"
#include "ListOps.H"
#include "PstreamCombineReduceOps.H"
#include "mathematicalConstants.H"
#include "clockTime.H"
#include "dictKeys.H"
#include "mortonOrder.H"
#include "stringOps.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::DPICloud<CloudType>::setModels()
{
    const dictionary& props = this->particleProperties();

    // The top-level keys: those the stock KinematicCloud reads (solution,
    // constantProperties, subModels, cloudFunctions), then those read here
    // and by dpiFluidCoupling. Each reader below checks its own dictionary
    dictKeys::warnUnknown
    (
        props,
        {
            "solution", "constantProperties", "subModels", "cloudFunctions",
            "dem", "injectors", "fluidCoupling", "trace", "agglomerates"
        }
    );

    if (!props.found("dem"))
    {
        FatalIOErrorInFunction(props)
            << "Missing sub-dictionary 'dem' in " << props.name() << nl
            << "    it holds the DEM time step, materials and contact models"
            << exit(FatalIOError);
    }

    // The engine's own keys first, so that a typo is named before a
    // reader stops on the entry it misses
    demEngine::warnUnknownKeys(props.subDict("dem"));
    engine_.reset(new demEngine(props.subDict("dem"), &this->mesh()));
    engine_->setTime(this->mesh().time().value());

    // Gas-particle forces: none unless fluidCoupling/forces
    coupling_.reset
    (
        new dpiFluidCoupling
        (
            props, this->mesh(), this->U(), this->rho(), this->mu(),
            engine_->materials()
        )
    );

    // Parallel: the DEM either on its own partition of the parcels (load
    // balanced, dem/loadBalance rcb, the default) or on the mesh owners
    // with a halo of the mesh sub-domains' boxes
    const dictionary& demDict = props.subDict("dem");
    if (demPartition::selected(demDict))
    {
        domain_.reset(new demPartition(demDict, engine_(), this->mesh()));
    }
    else
    {
        domain_.reset(new meshDomain(engine_(), this->mesh()));
    }

    injectors_.reset
    (
        new dpiInjectors(props, this->mesh(), engine_->materials())
    );

    if (props.found("trace"))
    {
        const Time& time = this->mesh().time();
        trace_.reset
        (
            new demTrace
            (
                props.subDict("trace"),
                time.globalPath()/"postProcessing"/this->name()/"trace"
               /time.timeName()
            )
        );
    }

    {
        const Time& time = this->mesh().time();
        agglomerates_.reset
        (
            new agglomerateTracker
            (
                props.subOrEmptyDict("agglomerates"),
                time.globalPath()/"postProcessing"/this->name()/"agglomerates"
               /time.timeName()
            )
        );
    }

    reports_.reset
    (
        new demReports
        (
            engine_(),
            this->mesh().time().globalPath()/"postProcessing"/this->name(),
            this->mesh().time().timeName()
        )
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::readCloudFields()
{
    // A missing field file is OpenFOAM's bare "cannot find file" (a
    // FatalError): caught to say how such a time comes about and what to
    // run. Any other error goes on as OpenFOAM reports it
    const bool throwing = FatalError.throwExceptions();
    const bool ioThrowing = FatalIOError.throwExceptions();
    auto restore = [&]()
    {
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(ioThrowing);
    };
    string missing;
    try
    {
        parcelType::readFields(*this);
    }
    catch (const IOerror& err)
    {
        restore();
        IOerror other(err);
        other.dontThrowExceptions();
        other.exit();
    }
    catch (const error& err)
    {
        restore();
        missing = err.message();
        if (missing.find("cannot find file") == string::npos)
        {
            error other(err);
            other.dontThrowExceptions();
            other.exit();
        }
    }
    restore();
    if (missing.empty())
    {
        return;
    }

    cloudRecord::refuseMissingFields
    (
        this->db().time(), this->name(), missing
    );
}


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
        checkRestartCloud(dpiDict);
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
        escapes_.nGone(), !injectors_->empty()
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::checkRestartCloud(const dictionary& dpiDict)
{
    const word timeName(this->db().time().timeName());
    const dictionary& demDict = this->particleProperties().subDict("dem");
    const demMaterials& mat = engine_->materials();

    labelList typeIds(this->size());
    labelList ids(this->size());
    scalarList ds(this->size()), Ns(this->size()), rhos(this->size());
    label i = 0;
    for (const parcelType& p : *this)
    {
        typeIds[i] = p.typeId();
        ids[i] = p.globalId();
        ds[i] = p.d();
        Ns[i] = p.N();
        rhos[i] = p.rho();
        ++i;
    }

    // Types by name; what the parcels were made with unchanged
    const labelList newIndex
    (
        restartCheck::mapTypes
        (
            dpiDict, demDict, mat, timeName, typeIds, ids, ds, Ns, rhos
        )
    );
    if (newIndex.size())
    {
        for (parcelType& p : *this)
        {
            p.typeId() = newIndex[p.typeId()];
        }
    }

    // Unique ids, and contact histories that name parcels and walls that
    // exist. A partner that was issued but is gone (it left through an
    // outlet in the step the time was written) is a finished contact:
    // dropped. One never issued, or a wall not in dem/walls, is refused.
    const labelHashSet all(restartCheck::globalIds(ids, timeName));
    const label nIssued = dpiDict.lookupOrDefault<label>("nextGlobalId", 0);
    const label nWalls = engine_->walls().size();
    label nDropped = 0;
    string reason;
    for (parcelType& p : *this)
    {
        restartCheck::checkHistory
        (
            p.globalId(), p.contactKeys(), p.contactXi(), all, nIssued,
            nWalls, timeName, reason, nDropped
        );
    }

    restartCheck::refuseIfAny(reason, this->outputProperties());

    reduce(nDropped, sumOp<label>());
    if (nDropped)
    {
        Info<< "    Dropped " << nDropped << " contact histories with parcels"
            << " that left the domain before time " << timeName << endl;
    }
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
    if (engine_.valid())
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
        restartCheck::writeTypes(dpiDict, engine_->materials(), typeIds, ds);
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
    if (!injectors_->due(t0, t1, specs, owner, cell, typeIds))
    {
        return 0;
    }

    const demMaterials& mat = engine_->materials();
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
        p.d() = (s.d > 0 ? s.d : mat.diameter(typei));
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


template<class CloudType>
void Foam::DPICloud<CloudType>::orderParcels()
{
    engine_->orderRows(state_);
    if (!engine_->alongCurve())
    {
        return;
    }

    // The pairs are swept in key order, so rows in that order are read one
    // after the other and a row's partners lie near it in memory. The keys
    // move only as parcels cross cells, and a reorder costs a neighbour
    // build (the search sees new rows): a few rows out of place are left
    const UList<uint64_t>& keys = state_.key;
    if (mortonOrder::nDescents(keys) <= keys.size()/100)
    {
        return;
    }

    labelList order;
    sortedOrder(keys, order);
    state_.reorder(order);

    // The parcels to the same order (relinked, not copied: each in turn to
    // the list's end), so that the rows come in it at the next steps
    List<parcelType*> parcels(this->size());
    label i = 0;
    for (parcelType& p : *this)
    {
        parcels[i++] = &p;
    }
    for (const label k : order)
    {
        this->append(this->remove(parcels[k]));
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::copyToState(const bool contactForcesValid)
{
    state_.clear();
    state_.reserve(this->size());

    for (const parcelType& p : *this)
    {
        const label row = state_.append
        (
            p.xDEM(),
            p.U(),
            p.omega(),
            0.5*p.d(),
            p.primaryMass(),
            p.N(),
            p.typeId(),
            p.globalId()
        );
        state_.fContact[row] = p.f();
        state_.tContact[row] = p.torque();
    }
    state_.contactForcesValid = contactForcesValid;

    // With the DEM's own partition the histories travel with the rows
    // every fluid step: the parcels' lists are moved, not copied, to the
    // partition (which gives them to the engine), and come back with
    // the rows (demDomain::end), so a history is held once while the DEM
    // runs
    if (domain_->historiesTravel())
    {
        rowKeys_.setSize(state_.size());
        rowXi_.setSize(state_.size());
        label i = 0;
        for (parcelType& p : *this)
        {
            rowKeys_[i].transfer(p.contactKeys());
            rowXi_[i].transfer(p.contactXi());
            ++i;
        }
        return;
    }

    // The engine keeps the histories between steps; the parcels' copies
    // are loaded once, at the first step (a restart)
    if (!historyLoaded_)
    {
        // The store sized once (it would otherwise grow by doubling,
        // copying itself at each growth; measured on a 50,000 restart this
        // does not move the run's peak memory)
        label nContacts = 0;
        for (const parcelType& p : *this)
        {
            nContacts += p.contactKeys().size();
        }
        engine_->reserveHistory(nContacts);

        for (const parcelType& p : *this)
        {
            engine_->setHistory(p.globalId(), p.contactKeys(), p.contactXi());
        }
        historyLoaded_ = true;
    }
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
        setModels();

        if (readFields)
        {
            readCloudFields();
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
    s.position.setSize(n);
    s.N.setSize(n);
    s.api.setSize(n);
    s.globalId.setSize(n);
    s.agglomerateId.setSize(n);
    s.d.setSize(n);
    s.rho.setSize(n);
    s.cell.setSize(n);

    label i = 0;
    for (const parcelType& p : *this)
    {
        s.position[i] = p.xDEM();
        s.N[i] = p.N();
        s.api[i] = engine_.valid() && engine_->materials().api(p.typeId());
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
    if (coupling_.valid() && coupling_->voidFraction())
    {
        return coupling_->voidFraction()->theta(*this);
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
    e.api = engine_->materials().api(p.typeId());
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
    WarningInFunction
        << "Parcel " << p.globalId() << " passed through wall patch "
        << pp.name() << " (DEM position " << p.xDEM()
        << "); removed. Is the patch listed in dem/walls?" << endl;
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
    if (trace_.valid())
    {
        labelList ids(this->size());
        label i = 0;
        for (const parcelType& p : *this)
        {
            ids[i++] = p.globalId();
        }
        trace_->warnAbsent
        (
            ids, nextGlobalId_, this->db().time().timeName()
        );
    }
    return when;
}


template<class CloudType>
Foam::demObserver* Foam::DPICloud<CloudType>::stepObserver(const scalar t0)
{
    if (!observer_ && trace_.valid())
    {
        trace_->beginStep(t0, engine_->timeStep());
        return trace_.get();
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
    demState& rows = domain_->rows();
    if (!coupling_->subStepForces())
    {
        engine_->evolve(rows, Dt, g, obs);
        return;
    }

    // One engine call for the fluid step; the hook sets the forces before
    // every sub-step
    autoPtr<dpiSubStepForces> forces
    (
        coupling_->newSubStepForces
        (
            rows.owned(), domain_->vectorColumns(), domain_->scalarColumns(),
            engine_->timeStep(), engine_->nSubSteps(Dt)
        )
    );
    engine_->evolve(rows, Dt, g, obs, forces.get());
    coupling_->subStepResults(forces(), vecOut, scaOut);
}


template<class CloudType>
void Foam::DPICloud<CloudType>::composeEscapes()
{
    const label n = this->size();
    labelList ids(n);
    scalarList d(n), rho(n);
    boolList carrier(n);
    const demMaterials& mat = engine_->materials();
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
    copyToState(nInjected == 0);
    if (!domain_->ordersRows())
    {
        orderParcels();
    }
    const word checkWhen(startCheckDue(nInjected));
    demObserver* obs = stepObserver(t1 - Dt);

    // The run-time check (demEngine::checkStep) sees the whole fluid step
    engine_->resetStepDiagnostics();

    // The gas at the parcels: held forces, or the states the forces of
    // every sub-step start from
    List<vectorField> vecIn, vecOut, vecBack;
    List<scalarField> scaIn, scaOut, scaBack;
    coupling_->startFluidStep(*this, state_, Dt, vecIn, scaIn);

    // The rows to where the DEM runs, the start check there, the
    // sub-steps, the agglomerates labelled, every row back to its parcel
    scalar range = 0, margin = 0;
    if (domain_->halo())
    {
        engine_->haloReach(state_, Dt, range, margin);
    }
    domain_->begin(state_, vecIn, scaIn, rowKeys_, rowXi_, range, margin);
    if (checkWhen.size())
    {
        engine_->checkStartState(domain_->rows(), checkWhen);
    }
    subSteps(Dt, g, obs, vecOut, scaOut);
    agglomerates_->update
    (
        domain_->rows(), engine_->materials(), domain_->agglomerateIds(),
        domain_->halo()
    );
    List<parcelType*> parcels(this->size());
    {
        label i = 0;
        for (parcelType& p : *this)
        {
            parcels[i++] = &p;
        }
    }
    domain_->end
    (
        state_,
        [&parcels](const label i, demDomain::rowBack& row)
        {
            setParcel(*parcels[i], row);
        },
        vecOut, scaOut, vecBack, scaBack
    );
    coupling_->finishFluidStep(*this, vecBack, scaBack, Dt);

    agglomerates_->write(t1);
    reports_->write
    (
        engine_(), *domain_, t1, returnReduce(this->size(), sumOp<label>())
    );
    engine_->checkStep(this->db().time().timeName());
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

    const demMaterials& mat = engine_->materials();
    forAll(mat.names(), typei)
    {
        if (!mat.isParticleType(typei))
        {
            continue;
        }
        Info<< "    Primaries of type " << mat.names()[typei]
            << " = " << nPrimaries(typei) << nl;
    }

    const agglomerateTracker::statistics& ag = agglomerates_->stats();
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
