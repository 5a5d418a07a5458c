/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "DPICloud.H"
#include "writtenTimes.H"
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
void Foam::DPICloud<CloudType>::checkStockModels(const dictionary& cloudDict)
{
    // KinematicCloud reads its sub-models (and needs the four model keys),
    // but dpiFoam's parcels are moved by the DEM: a stock model named there
    // would do nothing or, for injection, add parcels without a DEM type or
    // id. A DPMFoam user's habit gets a message saying where the dpiFoam
    // model goes (doc/models.md)
    const dictionary sub(cloudDict.subOrEmptyDict("subModels"));

    struct stock { const char* key; bool isDict; const char* instead; };
    const stock models[] =
    {
        {"injectionModels", true,
            "injectors { <name> { type singleParticles | regionPacking; ..."
            " } } at the top level of the cloud dictionary"},
        {"particleForces", true,
            "fluidCoupling { forces { wenYuParcel {} pressureGradient {} } }"},
        {"dispersionModel", false,
            "fluidCoupling { turbulentDispersion { ... } } (the LES subgrid"
            " velocity)"},
        {"patchInteractionModel", false,
            "dem { walls { <name> { type patch; patches (...); material"
            " ...; } } } (walls are DEM contacts)"},
        {"stochasticCollisionModel", false,
            "dem { normalModel ...; tangentialModel ...; } (every contact"
            " is resolved by the DEM)"},
        {"surfaceFilmModel", false, "nothing: dpiFoam has no surface film"}
    };

    for (const stock& m : models)
    {
        bool named = false;
        word what;
        if (m.isDict)
        {
            const dictionary* d = sub.findDict(m.key);
            named = d && d->size();
            what = named ? word(d->toc()[0]) : word::null;
        }
        else if (sub.found(m.key))
        {
            what = sub.get<word>(m.key);
            named = (what != "none");
        }
        if (named)
        {
            FatalIOErrorInFunction(sub)
                << "subModels/" << m.key << " names " << what << " in "
                << sub.name() << ", a stock KinematicCloud model that"
                << " dpiFoam does not use (its parcels are moved by the DEM)."
                << nl << "    Leave it " << (m.isDict ? "empty ({})" : "none")
                << " and use " << m.instead << exit(FatalIOError);
        }
    }
}


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

    checkStockModels(props);

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
        partition_.reset(new demPartition(demDict, engine_(), this->mesh()));
    }
    else if (Pstream::parRun())
    {
        halo_.reset(new processorHalo(this->mesh()));
        engine_->setHalo(halo_.get(), true);
    }

    injectors_.clear();
    if (props.found("injectors"))
    {
        const dictionary& injDict = props.subDict("injectors");
        const wordList names(injDict.toc());
        injectors_.setSize(names.size());
        forAll(names, i)
        {
            injectors_.set
            (
                i,
                dpiInjectionModel::New(names[i], injDict.subDict(names[i]), &engine_->materials())
            );
        }
        checkInjectorBounds(injDict);
    }

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

    if (Pstream::master())
    {
        // postProcessing/<cloud>/<name>/<startTime>/<name>.dat
        const Time& time = this->mesh().time();
        auto series = [&](const word& name, const label digits)
        {
            const fileName dir
            (
                time.globalPath()/"postProcessing"/this->name()/name
               /time.timeName()
            );
            mkDir(dir);
            autoPtr<OFstream> file(new OFstream(dir/(name + ".dat")));
            file().precision(digits);
            return file;
        };

        diagFile_ = series("demDiagnostics", 10);
        diagFile_()
            << "# DEM diagnostics at the end of every fluid step" << nl
            << "# time kineticEnergy[J] rotationalEnergy[J] nPairContacts"
            << " nWallContacts maxOverlap/R* nParcels" << nl;

        perfFile_ = series("demPerformance", 8);
        perfFile_()
            << "# DEM cost on the master processor at the end of every"
            << " fluid step: wall-clock seconds since this run started,"
            << " summed (as the log's DEM performance line)" << nl
            << "# time subSteps pair wall neighbour integrate haloExchange"
            << " subStepFluidForces searches nearBuilds" << nl;

        if (engine_->contactStats())
        {
            statsFile_ = series("contactStatistics", 10);
            engine_->contactStats()->writeHeader(statsFile_());
        }
    }

    balance_.reset
    (
        new parcelBalance
        (
            this->mesh().time().globalPath()/"postProcessing"/this->name()
           /"parcelBalance"/this->mesh().time().timeName()
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

    const Time& time = this->db().time();
    const fileName cloudDir(time.timeName()/cloud::prefix/this->name());
    const bool decomposedToo =
        isDir(time.globalPath()/"processor0"/time.timeName());
    // (collective in parallel, where a processor may stop here alone)
    const word last
    (
        Pstream::parRun()
      ? word::null
      : writtenTimes::lastComplete(time.path(), time.value(), this->name())
    );
    FatalIOErrorInFunction(time.controlDict())
        << "The restart time " << time.timeName() << " (startFrom/startTime"
        << " in " << time.controlDict().name() << ") has the parcels of"
        << " cloud " << this->name() << " but not all their fields: "
        << stringOps::trim(missing).c_str() << nl;
    if (decomposedToo && !Pstream::parRun())
    {
        FatalIOError
            << "    The time was reconstructed from processor0/"
            << time.timeName() << " ...: reconstructPar without a"
            << " lagrangian field selection leaves out the contact"
            << " histories (contactKeys, contactXi). Run reconstructPar"
            << " -time " << time.timeName() << " -lagrangianFields"
            << " '(\".*\")', or restart in parallel from the processor"
            << " directories";
    }
    else
    {
        FatalIOError
            << "    The cloud's files in " << cloudDir << " were deleted or"
            << " not copied (every field a run writes is needed)";
        if (last.size())
        {
            FatalIOError
                << "; restore them, or restart from " << last
                << " (startFrom startTime; startTime " << last << ";)";
        }
    }
    FatalIOError<< exit(FatalIOError);
}


template<class CloudType>
void Foam::DPICloud<CloudType>::checkInjectorBounds
(
    const dictionary& injDict
) const
{
    // Before any packing: a region outside the mesh would otherwise be
    // packed first and fail on what the packing cannot reach, never
    // naming the mesh (the parcels' own positions are checked against the
    // mesh's cells when injected)
    const boundBox& meshBb = this->mesh().bounds();
    boundBox grown(meshBb);
    grown.inflate(1e-9);
    forAll(injectors_, i)
    {
        const boundBox bb(injectors_[i].bounds());
        if (bb.valid() && !grown.contains(bb))
        {
            FatalIOErrorInFunction(injDict.subDict(injectors_[i].name()))
                << "Injector " << injectors_[i].name() << " in "
                << injDict.name() << " places its particles in "
                << bb.min() << ' ' << bb.max() << ", outside the mesh"
                << " (bounds " << meshBb.min() << ' ' << meshBb.max()
                << ")." << nl << "    Move its positions or region"
                << " inside the mesh (lengths in metres)"
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::readState()
{
    const dictionary dpiDict
    (
        this->outputProperties().subOrEmptyDict("dpiCloud")
    );

    nextGlobalId_ = dpiDict.lookupOrDefault<label>("nextGlobalId", 0);

    const Time& time = this->db().time();
    const label nParcels = returnReduce(this->size(), sumOp<label>());

    // Parcels without the state written with them (uniform/ deleted or
    // not copied): the models, the type table and the ids issued are
    // unknown, and nothing below could be checked
    const bool stateMissing = !this->outputProperties().found("dpiCloud");
    if (nParcels && returnReduce(stateMissing, orOp<bool>()))
    {
        const word last
        (
            writtenTimes::lastComplete(time.path(), time.value(), this->name())
        );
        FatalIOErrorInFunction(this->outputProperties())
            << "Time " << time.timeName() << " has " << nParcels
            << " parcels of cloud " << this->name() << " but not the cloud"
            << " state written with them ("
            << this->outputProperties().objectPath() << " is missing)."
            << nl << "    Without it the models, the type table and the"
            << " ids issued are unknown and a restart cannot be checked."
            << " Restore " << time.timeName() << "/uniform (written with"
            << " every time; decomposePar and reconstructPar copy it)";
        if (last.size())
        {
            FatalIOError<< " or restart from " << last;
        }
        FatalIOError<< "." << exit(FatalIOError);
    }

    // A restart may change material and model coefficients, not the
    // choice of models: the state written (histories, forces) belongs to
    // the models that wrote it
    const dictionary& demDict = this->particleProperties().subDict("dem");
    const dictionary written(dpiDict.subOrEmptyDict("models"));
    for (const word& key : written.toc())
    {
        const word before(written.get<word>(key));
        const word now(demDict.get<word>(key));
        if (before != now)
        {
            FatalIOErrorInFunction(demDict)
                << "Restart with " << key << " " << now << " in dictionary "
                << demDict.name() << ", but the state at time "
                << this->db().time().timeName() << " was written with "
                << key << " " << before << "." << nl
                << "    A restart may change the models' coefficients, not"
                << " the models: set " << key << " " << before << ";"
                << exit(FatalIOError);
        }
    }

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

    checkCloudPresent(nextGlobalId_);
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
        labelField& keys = p.contactKeys();
        vectorField& xi = p.contactXi();
        label n = 0;
        forAll(keys, k)
        {
            const label key = keys[k];
            const bool isWall = key < 0;
            const label wall = isWall ? (-1 - key) % 128 : -1;
            if
            (
                reason.empty()
             && ((!isWall && key >= nIssued) || (isWall && wall >= nWalls))
            )
            {
                reason =
                    "Parcel " + Foam::name(p.globalId()) + " at time "
                  + timeName + " has a contact history with "
                  + (
                        isWall
                      ? "wall " + Foam::name(wall) + ", but dem/walls has "
                        + Foam::name(nWalls)
                      : "parcel " + Foam::name(key) + ", but only "
                        + Foam::name(nIssued) + " ids were issued"
                    )
                  + ": the contactKeys field was edited or belongs to"
                  + " another case.";
            }
            if (!isWall && !all.found(key))
            {
                ++nDropped;
                continue;
            }
            keys[n] = key;
            xi[n] = xi[k];
            ++n;
        }
        keys.setSize(n);
        xi.setSize(n);
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
void Foam::DPICloud<CloudType>::checkCloudPresent(const label nIssued) const
{
    // A start time without parcels is legitimate (injection ahead, or the
    // gas alone), unless the state written with that time says parcels were
    // issued and did not all leave: then the cloud was not written or not
    // reconstructed, and going on would silently run without the powder
    const label nParcels = returnReduce(this->size(), sumOp<label>());
    if (nParcels > 0)
    {
        return;
    }

    // The counters live on the master (readState)
    const label nGone = escapes_.nGone();

    const Time& time = this->db().time();
    const word cloudDir(time.timeName()/cloud::prefix/this->name());
    if (nIssued > nGone)
    {
        // Never advise going on without the cloud: name the latest time
        // that has it (a parallel run's times may need reconstructing)
        const word last
        (
            writtenTimes::lastComplete(time.path(), time.value(), this->name())
        );
        FatalIOErrorInFunction(this->outputProperties())
            << "Time " << time.timeName() << " has no parcels of"
            << " cloud " << this->name() << " (" << cloudDir << "/positions"
            << " not found or empty), but the cloud state in "
            << this->outputProperties().objectPath() << " says " << nIssued
            << " parcels were issued and " << nGone << " left the domain."
            << nl << "    Restart from a time written with the cloud";
        if (last.size())
        {
            FatalIOError
                << ": the latest before this one is " << last
                << " (startFrom startTime; startTime " << last << ";)";
        }
        FatalIOError
            << ". After a parallel run, reconstructPar -lagrangianFields"
            << " '(\".*\")' writes the cloud into the case's times."
            << exit(FatalIOError);
    }

    if (injectors_.empty())
    {
        WarningInFunction
            << "No parcels at time " << this->db().time().timeName()
            << " (" << cloudDir << " is empty or missing) and no injectors in "
            << this->particleProperties().name()
            << ": the cloud stays empty" << endl;
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::storeCounters()
{
    dictionary dpiDict;
    dpiDict.add("nextGlobalId", nextGlobalId_);

    dictionary models;
    const dictionary& demDict = this->particleProperties().subDict("dem");
    for
    (
        const word key
      : {"normalModel", "tangentialModel", "rollingModel", "cohesionModel"}
    )
    {
        models.add(key, demDict.get<word>(key));
    }
    dpiDict.add("models", models);

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
    const demMaterials& mat = engine_->materials();

    // The injection's own time in the log: the set-up figure of a run
    // holds it among the mesh, the fields and the first fluid step
    const clockTime timer;

    // The curve's cell for `order morton`: the largest particle
    const scalar dMax = mat.maxDiameter();

    DynamicList<injectionSpec> specs;
    forAll(injectors_, i)
    {
        const label start = specs.size();
        injectors_[i].inject(t0, t1, specs);
        injectors_[i].order(specs, start, dMax);
    }

    if (returnReduce(specs.empty(), andOp<bool>()))
    {
        return 0;
    }

    const fvMesh& mesh = this->mesh();

    // Owner processor of each position: local octree search, then one
    // element-wise min over processors (lowest processor wins, so the owner
    // does not depend on search order)
    const label notFound = Pstream::nProcs();
    labelList owner(specs.size(), notFound);
    labelList cell(specs.size(), -1);
    forAll(specs, i)
    {
        cell[i] = mesh.findCell(specs[i].position);
        if (cell[i] >= 0)
        {
            owner[i] = Pstream::myProcNo();
        }
    }
    Pstream::listCombineGather(owner, minEqOp<label>());
    Pstream::listCombineScatter(owner);

    forAll(specs, i)
    {
        if (owner[i] == notFound)
        {
            FatalIOErrorInFunction(this->particleProperties())
                << "A particle of type " << specs[i].type
                << " is injected at " << specs[i].position
                << ", outside the mesh (bounds " << mesh.bounds() << ")." << nl
                << "    Check 'injectors' in " << this->particleProperties().name()
                << exit(FatalIOError);
        }
    }

    // Types are checked on every processor so that all stop together
    const dictionary& injDict = this->particleProperties().subDict("injectors");
    forAll(specs, i)
    {
        const label typei = mat.typeIndex(specs[i].type, injDict, "type");
        if (!mat.isParticleType(typei))
        {
            const fileName typeDict
            (
                injDict.parent().name() + ".dem.types." + specs[i].type
            );
            FatalIOErrorInFunction(injDict)
                << "Injected type " << specs[i].type << " has no 'diameter'"
                << " in dictionary " << typeDict.c_str() << ": a type"
                << " without one is a wall material." << nl
                << "    Give type " << specs[i].type << " a diameter and a"
                << " density to inject it" << exit(FatalIOError);
        }
    }

    forAll(specs, i)
    {
        const injectionSpec& s = specs[i];

        // Same on every processor: ids follow the list order
        const label gid = nextGlobalId_ + i;

        if (owner[i] != Pstream::myProcNo())
        {
            continue;
        }

        const label typei = mat.typeIndex(s.type, injDict, "type");

        parcelType* pPtr = new parcelType(mesh, s.position, cell[i]);
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
    // the rows (demPartition::collect), so a history is held once while
    // the DEM runs
    if (partition_.valid())
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


template<class CloudType>
void Foam::DPICloud<CloudType>::copyFromState()
{
    DynamicList<label> keys;
    DynamicList<vector> xi;

    label i = 0;
    for (parcelType& p : *this)
    {
        setParcel
        (
            p, state_.x[i], state_.v[i], state_.omega[i],
            state_.fContact[i], state_.tContact[i], agglomerateIds_[i]
        );
        keys.clear();
        xi.clear();
        engine_->history(p.globalId(), keys, xi);
        p.contactKeys() = keys;
        p.contactXi() = xi;
        ++i;
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::checkContacts()
{
    const demDiagnostics& d = engine_->diagnostics();

    // The largest values over all processors, with the contact of the
    // processor that holds them (ties: the largest ids, the same anywhere)
    auto worst = [](const scalar local, const label pair[2], labelPair& ids)
    {
        const scalar global = returnReduce(local, maxOp<scalar>());
        ids = labelPair(labelMin, labelMin);
        if (local == global)
        {
            ids = labelPair(pair[0], pair[1]);
        }
        reduce(ids.first(), maxOp<label>());
        reduce(ids.second(), maxOp<label>());
        return global;
    };
    labelPair overlapIds, approachIds;
    const scalar overlap = worst(d.stepMaxOverlapRatio, d.overlapPair, overlapIds);
    const scalar approach = worst(d.stepMaxApproach, d.approachPair, approachIds);

    auto contactName = [this](const labelPair& ids)
    {
        const label b = ids.second();
        return
            "parcel " + Foam::name(ids.first())
          + (
                b >= 0
              ? " with parcel " + Foam::name(b)
              : " with wall " + engine_->walls()[-1 - b].name()
            );
    };

    const scalar vMax = engine_->maxImpactVelocity();
    const word t(this->db().time().timeName());

    const scalar travel = returnReduce(d.stepMaxTravel, maxOp<scalar>());
    if (travel > 1)
    {
        const label id = returnReduce
        (
            d.stepMaxTravel == travel ? d.travelId : labelMin,
            maxOp<label>()
        );
        FatalErrorInFunction
            << "At time " << t << " parcel " << id << " moves "
            << travel << " radii per DEM step (|v| dem/timeStep / r): it"
            << " can cross a wall or another parcel between two steps"
            << " without any contact being seen." << nl
            << "    Check what drives it (the time step was checked for"
            << " timeStepCheck/maxImpactVelocity " << vMax << " m/s), or"
            << " lower dem/timeStep. The last written time is intact."
            << exit(FatalError);
    }

    if (overlap > engine_->overlapRefuse())
    {
        FatalErrorInFunction
            << "At time " << t << " the contact of "
            << contactName(overlapIds).c_str() << " reached an overlap of "
            << overlap << " R*, above dem/overlapCheck/refuse "
            << engine_->overlapRefuse() << ": the contact is far outside"
            << " what Hertz contact describes, and a little more takes a"
            << " parcel through its partner." << nl
            << "    The fastest approach in this fluid step was " << approach
            << " m/s"
            << (
                   approachIds.first() >= 0
                 ? " (" + contactName(approachIds) + ")"
                 : std::string()
               ).c_str()
            << "; the time step was checked for"
            << " timeStepCheck/maxImpactVelocity "
            << vMax << " m/s. Check the speeds and forces that drive it"
            << " (gravity, cohesion, drag), raise maxImpactVelocity to what"
            << " the scene reaches (the start-up check then says whether"
            << " dem/timeStep and the stiffness resolve it), or raise"
            << " dem/overlapCheck/refuse to go on. The last written time is"
            << " intact." << exit(FatalError);
    }
    if (overlap > engine_->overlapWarn() && overlap > 2*warnedOverlap_)
    {
        WarningInFunction
            << "At time " << t << " the contact of "
            << contactName(overlapIds).c_str() << " reached an overlap of "
            << overlap << " R*, above dem/overlapCheck/warn "
            << engine_->overlapWarn() << " (Hertz contact assumes small"
            << " overlaps; the run stops at refuse "
            << engine_->overlapRefuse() << "). Said again if it doubles."
            << endl;
        warnedOverlap_ = overlap;
    }
    if (approach > vMax && approach > 2*warnedApproach_)
    {
        WarningInFunction
            << "At time " << t << " " << contactName(approachIds).c_str()
            << " approached at " << approach << " m/s, above"
            << " timeStepCheck/maxImpactVelocity " << vMax << " m/s that"
            << " the time step and overlaps were checked for at start-up:"
            << " raise it to what the scene reaches. Said again if it"
            << " doubles." << endl;
        warnedApproach_ = approach;
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::writeDiagnostics()
{
    const demDiagnostics& d = engine_->diagnostics();

    const scalar ke = returnReduce(d.kineticEnergy, sumOp<scalar>());
    const scalar re = returnReduce(d.rotationalEnergy, sumOp<scalar>());
    const label nPair = returnReduce(d.nPairContacts, sumOp<label>());
    const label nWall = returnReduce(d.nWallContacts, sumOp<label>());
    const scalar maxOverlap = returnReduce(d.maxOverlapRatio, maxOp<scalar>());
    const label nParcels = returnReduce(this->size(), sumOp<label>());

    if (diagFile_.valid())
    {
        diagFile_()
            << this->db().time().value() << ' ' << ke << ' ' << re
            << ' ' << nPair << ' ' << nWall << ' ' << maxOverlap
            << ' ' << nParcels << endl;
    }

    if (perfFile_.valid())
    {
        const demEngine& e = engine_();
        perfFile_()
            << this->db().time().value() << ' ' << e.nSteps()
            << ' ' << e.timePair() << ' ' << e.timeWall()
            << ' ' << e.timeNeighbour() << ' ' << e.timeIntegrate()
            << ' ' << e.timeHalo() << ' ' << e.timeExternal()
            << ' ' << e.neighbours().nBuilds() << ' ' << e.nNearBuilds()
            << endl;
    }

    if (const contactStatistics* stats = engine_->contactStats())
    {
        // collective: every processor's counts go to the master
        stats->write
        (
            this->db().time().value(),
            statsFile_.valid() ? statsFile_() : Snull
        );
    }

    balance_->sample
    (
        this->db().time().value(),
        partition_.valid() ? partition_->nDemOwned() : state_.owned(),
        partition_.valid() ? partition_->nDemRows() : state_.size(),
        d.nPairContacts
    );

    checkContacts();

    Info<< "    DEM: " << engine_->nSteps() << " sub-steps so far"
        << ", contacts (pair, wall) = (" << nPair << ", " << nWall << ")"
        << ", max overlap/R* = " << maxOverlap
        << ", kinetic energy = " << ke << ", rotational = " << re << nl;

    // Collective builds: the same counts on every processor
    const processorHalo* halo =
        partition_.valid() ? &partition_->halo() : halo_.get();
    if (halo)
    {
        Info<< "    DEM halo: " << halo->nGhosts() << " ghost rows on the "
            << "master, " << halo->nBuilds() << " builds so far, "
            << halo->nRebuilds() << " of them within a fluid step" << nl;
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::haloReach
(
    const scalar Dt,
    scalar& range,
    scalar& margin
) const
{
    // The contact radii: parcels that meet each other at grown radii
    // (coarseGrainingModel) reach that far
    scalar rMax =
        engine_->materials().coarseGraining().maxRadius
        (
            state_.r, state_.typeId
        );
    scalar vMax = 0;
    for (label row = 0; row < state_.size(); ++row)
    {
        vMax = max(vMax, mag(state_.v[row]));
    }
    reduce(rMax, maxOp<scalar>());
    reduce(vMax, maxOp<scalar>());

    range = engine_->interactionReach(rMax);

    // Enough for the fluid step while the parcels are slow (both parcels
    // of a pair travelling towards each other, 1.5 x the fastest speed for
    // moderate acceleration), so the halo is built once per fluid step; at
    // most one Verlet skin, past which the halo is built again within the
    // fluid step (processorHalo) rather than take in the fastest parcel's
    // travel over the whole of it. One skin: the halo is then built about
    // as often as that parcel's own travel rebuilds the neighbour lists
    // (half a skin); of 0.5, 1 and 2 skins it was the fastest on the
    // full-size inhaler's spray (tutorials/inhaler/README.md)
    margin = min(2*1.5*vMax*Dt, engine_->neighbours().skin());
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
    cloudCopyPtr_(nullptr),
    engine_(nullptr),
    injectors_(),
    nextGlobalId_(0),
    state_(),
    startChecked_(false),
    historyLoaded_(false),
    observer_(nullptr),
    trace_(nullptr),
    diagFile_(nullptr),
    perfFile_(nullptr),
    statsFile_(nullptr),
    agglomerates_(nullptr),
    halo_(nullptr),
    partition_(nullptr),
    rowKeys_(),
    rowXi_(),
    balance_(nullptr),
    agglomerateIds_(),
    escapes_(this->mesh().boundaryMesh()),
    escapeComposition_(),
    escapedThisStep_()
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
    cloudCopyPtr_(nullptr),
    engine_(nullptr),
    injectors_(),
    nextGlobalId_(c.nextGlobalId_),
    state_(),
    startChecked_(false),
    historyLoaded_(false),
    observer_(nullptr),
    trace_(nullptr),
    diagFile_(nullptr),
    perfFile_(nullptr),
    statsFile_(nullptr),
    agglomerates_(nullptr),
    halo_(nullptr),
    partition_(nullptr),
    rowKeys_(),
    rowXi_(),
    balance_(nullptr),
    agglomerateIds_(),
    escapes_(c.escapes_),
    escapeComposition_(),
    escapedThisStep_()
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
    cloudCopyPtr_(nullptr),
    engine_(nullptr),
    injectors_(),
    nextGlobalId_(c.nextGlobalId_),
    state_(),
    startChecked_(false),
    historyLoaded_(false),
    observer_(nullptr),
    trace_(nullptr),
    diagFile_(nullptr),
    perfFile_(nullptr),
    statsFile_(nullptr),
    agglomerates_(nullptr),
    halo_(nullptr),
    partition_(nullptr),
    rowKeys_(),
    rowXi_(),
    balance_(nullptr),
    agglomerateIds_(),
    escapes_(this->mesh().boundaryMesh()),
    escapeComposition_(),
    escapedThisStep_()
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
void Foam::DPICloud<CloudType>::fluidStep
(
    demStepper& stepper,
    const scalar Dt,
    const vector& g,
    demObserver* obs,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut
)
{
    if (!coupling_->active())
    {
        stepper.evolve(state_, Dt, g, obs);
        return;
    }

    coupling_->sample(*this, state_);

    if (!coupling_->subStepForces())
    {
        coupling_->setHeldForces(state_, Dt);
        stepper.evolve(state_, Dt, g, obs);
        return;
    }

    List<vectorField> vecIn;
    List<scalarField> scaIn;
    coupling_->packStates(vecIn, scaIn);
    subSteps
    (
        stepper, state_, coupling_->nRows(), vecIn, scaIn, vecOut, scaOut,
        Dt, g, obs
    );
}


template<class CloudType>
void Foam::DPICloud<CloudType>::finishFluidStep
(
    const List<vectorField>& vecOut,
    const List<scalarField>& scaOut,
    const scalar Dt
)
{
    if (!coupling_->active())
    {
        return;
    }
    if (coupling_->subStepForces())
    {
        coupling_->finishSubSteps(*this, vecOut, scaOut);
    }
    else
    {
        coupling_->finishHeld(*this, Dt);
    }
}


template<class CloudType>
void Foam::DPICloud<CloudType>::subSteps
(
    demStepper& stepper,
    demState& s,
    const label n,
    const List<vectorField>& vecIn,
    const List<scalarField>& scaIn,
    List<vectorField>& vecOut,
    List<scalarField>& scaOut,
    const scalar Dt,
    const vector& g,
    demObserver* obs
)
{
    // One engine call for the fluid step; the hook sets the forces before
    // every sub-step
    autoPtr<dpiSubStepForces> forces
    (
        coupling_->newSubStepForces
        (
            n, vecIn, scaIn, stepper.timeStep(), stepper.nSubSteps(Dt)
        )
    );
    stepper.evolve(s, Dt, g, obs, forces.get());
    coupling_->subStepResults(forces(), vecOut, scaOut);
}


template<class CloudType>
template<class TrackCloudType>
void Foam::DPICloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    const Time& time = this->db().time();
    const scalar Dt = time.deltaTValue();
    const scalar t1 = time.value();

    const label nInjected = inject(t1 - Dt, t1);

    copyToState(nInjected == 0);
    if (!partition_.valid())
    {
        // (the DEM's own partition orders its rows: demPartition)
        orderParcels();
    }

    // The start (or restart) and every injection: no parcel inside another
    // or a wall, no parcel without size (a collective decision, on the DEM
    // rows with their halo)
    word checkWhen;
    if (nInjected || !startChecked_)
    {
        checkWhen = startChecked_ ? "injected" : "at the start";
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
            trace_->warnAbsent(ids, nextGlobalId_, time.timeName());
        }
    }

    demObserver* obs = observer_;
    if (!obs && trace_.valid())
    {
        trace_->beginStep(t1 - Dt, engine_->timeStep());
        obs = trace_.get();
    }

    const vector g(this->g().value());

    // The run-time check (checkContacts) looks at the whole fluid step,
    // however many engine calls it takes (one per sub-step with the forces
    // updated every sub-step)
    engine_->resetStepDiagnostics();

    List<vectorField> vecOut;
    List<scalarField> scaOut;
    if (partition_.valid())
    {
        // The DEM on its own partition: the rows (with their fluid forces,
        // or with the frozen fluid states when the forces follow every
        // sub-step) go to their DEM owners and back
        scalar range, margin;
        haloReach(Dt, range, margin);
        partition_->setInputs(rowKeys_, rowXi_, range, margin, checkWhen);
        if (coupling_->subStepForces())
        {
            coupling_->sample(*this, state_);
            List<vectorField> vecIn;
            List<scalarField> scaIn;
            coupling_->packStates(vecIn, scaIn);
            partition_->distribute(state_, vecIn, scaIn);
            subSteps
            (
                engine_(), partition_->state(), partition_->state().owned(),
                partition_->vectorColumns(), partition_->scalarColumns(),
                vecOut, scaOut, Dt, g, obs
            );
        }
        else
        {
            // held forces set here, the DEM sub-steps at the DEM owners
            fluidStep(*partition_, Dt, g, obs, vecOut, scaOut);
        }

        // Labelled where the DEM rows are, then every row straight back
        // to its parcel (mesh row i is the i-th parcel of the list)
        agglomerates_->update
        (
            partition_->state(),
            engine_->materials(),
            partition_->agglomerateIds(),
            &partition_->halo()
        );
        List<parcelType*> parcels(this->size());
        {
            label i = 0;
            for (parcelType& p : *this)
            {
                parcels[i++] = &p;
            }
        }
        List<vectorField> vecBack;
        List<scalarField> scaBack;
        partition_->collect
        (
            state_,
            [&parcels](const label i, demPartition::rowBack& row)
            {
                parcelType& p = *parcels[i];
                setParcel
                (
                    p, row.x, row.v, row.omega, row.fContact, row.tContact,
                    row.agglomerateId
                );
                p.contactKeys().transfer(row.keys);
                p.contactXi().transfer(row.xi);
            },
            vecOut, scaOut, vecBack, scaBack
        );
        finishFluidStep(vecBack, scaBack, Dt);
    }
    else
    {
        if (halo_.valid())
        {
            // The owners' contact histories travel with the ghosts at every
            // build: a parcel new to this processor's halo brings the
            // contacts it already has (walls included), so they continue
            // here as they do at its owner
            scalar range, margin;
            haloReach(Dt, range, margin);
            halo_->build(state_, range, margin, &engine_());
            engine_->orderRows(state_, state_.owned());
        }
        if (checkWhen.size())
        {
            engine_->checkStartState(state_, checkWhen);
        }

        // DEM sub-steps with the fluid forces in state_.fExt, their
        // reaction into UTrans/UCoeff
        fluidStep(engine_(), Dt, g, obs, vecOut, scaOut);
        finishFluidStep(vecOut, scaOut, Dt);

        agglomerates_->update
        (
            state_,
            engine_->materials(),
            agglomerateIds_,
            halo_.get()
        );
        copyFromState();
    }
    agglomerates_->write(t1);

    writeDiagnostics();

    // What the agglomerates are made of, for the parcels this move
    // carries out
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
