/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiEmittedDose.H"
#include "fvMesh.H"
#include "cloud.H"
#include "mathematicalConstants.H"
#include "FixedList.H"
#include "devicePatches.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dpiEmittedDose, 0);
    addToRunTimeSelectionTable(functionObject, dpiEmittedDose, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- Unit density of the aerodynamic diameter [kg/m3]
    const Foam::scalar rho0 = 1000;

    //- The largest cutOff [m]: an inhaler's largest particles, carriers, are
    //  below 0.2 mm; 1 mm and up is a diameter typed in other units
    const Foam::scalar maxCutOff = 1e-3;

    //- The state's keys of the totals, in the order of fields()
    const char* const keys[] =
    {
        "emitted", "singlets", "agglomerates", "onCarriers", "fine",
        "primaries", "elsewhere"
    };

    //- The members of a dose, in the order of keys
    Foam::FixedList<Foam::scalar*, 7> fields
    (
        Foam::functionObjects::dpiEmittedDose::dose& d
    )
    {
        return
        {
            &d.emitted, &d.singlets, &d.agglomerates, &d.onCarriers,
            &d.fine, &d.primaries, &d.elsewhere
        };
    }

    //- A dose as a list (for a reduction)
    Foam::scalarList toList(Foam::functionObjects::dpiEmittedDose::dose& d)
    {
        const Foam::FixedList<Foam::scalar*, 7> f(fields(d));
        Foam::scalarList l(f.size());
        forAll(f, k)
        {
            l[k] = *f[k];
        }
        return l;
    }
}


// * * * * * * * * * * * * * * * * * * dose  * * * * * * * * * * * * * * * * //

void Foam::functionObjects::dpiEmittedDose::dose::add
(
    const scalar m,
    const scalar N,
    const bool onCarrier,
    const label agglomerateParcels,
    const bool isFine
)
{
    emitted += m;
    primaries += N;
    if (onCarrier)
    {
        onCarriers += m;
    }
    else if (agglomerateParcels <= 1)
    {
        singlets += m;
    }
    else
    {
        agglomerates += m;
    }
    if (isFine)
    {
        fine += m;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dpiEmittedDose::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Emitted dose of cloud " + cloudName_);
    writeHeaderValue(os, "aerodynamic cut-off [m]", cutOff_);
    writeHeaderValue(os, "shape factor of agglomerates", shapeFactor_);
    writeHeader
    (
        os,
        "API masses [kg], totals since the run began; emitted = left"
        " through the outlet patches; fine = d_ae < cut-off"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "loaded");
    writeTabbed(os, "emitted");
    writeTabbed(os, "singlets");
    writeTabbed(os, "agglomerates");
    writeTabbed(os, "onCarriers");
    writeTabbed(os, "fine");
    writeTabbed(os, "FPF_emitted");
    writeTabbed(os, "FPF_loaded");
    writeTabbed(os, "emittedPrimaries");
    os  << endl;
}


void Foam::functionObjects::dpiEmittedDose::writeOutletsHeader(Ostream& os)
{
    writeHeader(os, "Emitted dose of cloud " + cloudName_ + " per outlet");
    writeHeader
    (
        os,
        "API masses [kg], totals since the run began, per outlet patch:"
        " emitted, singlets, agglomerates, onCarriers, fine"
    );
    writeCommented(os, "Time");
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (const label patchi : patches_.sortedToc())
    {
        for (const word q : {"emitted", "singlets", "agglomerates",
                             "onCarriers", "fine"})
        {
            writeTabbed(os, pbm[patchi].name() + ':' + q);
        }
    }
    os  << endl;
}


void Foam::functionObjects::dpiEmittedDose::writeSizesHeader(Ostream& os)
{
    writeHeader
    (
        os,
        "Emitted dose of cloud " + cloudName_ + " by agglomerate size"
    );
    writeHeader
    (
        os,
        "API masses [kg] that left through the outlets, totals since the"
        " run began, by the API primaries in one copy of the agglomerate"
        " they left in; last column: on carriers"
    );
    writeCommented(os, "Time");
    label lower = 1;
    for (const label upper : sizeClasses_)
    {
        writeTabbed
        (
            os,
            upper == lower
          ? Foam::name(upper)
          : Foam::name(lower) + '-' + Foam::name(upper)
        );
        lower = upper + 1;
    }
    writeTabbed(os, Foam::name(lower) + '+');
    writeTabbed(os, "onCarriers");
    os  << endl;
}


void Foam::functionObjects::dpiEmittedDose::writeStagesHeader(Ostream& os)
{
    writeHeader
    (
        os,
        "Emitted dose of cloud " + cloudName_ + " by impactor stage: "
      + impactor_->describe()
    );
    writeHeader
    (
        os,
        "API masses [kg] that left through the outlets, totals since the"
        " run began, as the impactor's ideal stages sort them by"
        " aerodynamic diameter (IP+PS: the API on carriers); MMAD [m] and"
        " GSD of the stages (0: not bracketed)"
    );
    writeCommented(os, "Time");
    for (const word& b : impactor_->names())
    {
        writeTabbed(os, b);
    }
    writeTabbed(os, "MMAD");
    writeTabbed(os, "GSD");
    os  << endl;
}


Foam::label Foam::functionObjects::dpiEmittedDose::sizeClass
(
    const label n
) const
{
    forAll(sizeClasses_, k)
    {
        if (n <= sizeClasses_[k])
        {
            return k;
        }
    }
    return sizeClasses_.size();
}


void Foam::functionObjects::dpiEmittedDose::readState()
{
    const FixedList<scalar*, 7> t(fields(total_));
    forAll(t, k)
    {
        *t[k] = getProperty<scalar>(keys[k], 0);
    }

    // Per outlet by the patch's name: a restart that names other outlets
    // counts the new ones from zero
    dictionary outlets;
    getDict("outlets", outlets);
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const labelList ids(patches_.sortedToc());
    perOutlet_.setSize(ids.size());
    forAll(ids, i)
    {
        const dictionary* d = outlets.findDict(pbm[ids[i]].name());
        const FixedList<scalar*, 7> f(fields(perOutlet_[i]));
        forAll(f, k)
        {
            *f[k] = d ? d->lookupOrDefault<scalar>(keys[k], 0) : 0;
        }
    }

    // By size, if the classes are those of the run restarted
    bySize_ = scalarList(sizeClasses_.size() + 2, Zero);
    const labelList before(getProperty<labelList>("sizeClasses", labelList()));
    if (before == sizeClasses_)
    {
        dictionary d;
        getDict("bySize", d);
        forAll(bySize_, k)
        {
            bySize_[k] = d.lookupOrDefault<scalar>(word("class" + Foam::name(k)), 0);
        }
    }
    else if (before.size())
    {
        Info<< type() << ' ' << name() << ": sizeClasses " << sizeClasses_
            << " differ from the restarted run's " << before
            << ": sizes.dat counts from this start" << endl;
    }

    // By impactor stage, if the impactor is the restarted run's
    byStage_ = scalarList(impactor_.valid() ? impactor_->size() : 0, Zero);
    if (impactor_.valid())
    {
        const string was(getProperty<string>("impactor", string()));
        if (was == impactor_->describe())
        {
            dictionary d;
            getDict("byStage", d);
            forAll(byStage_, k)
            {
                byStage_[k] =
                    d.lookupOrDefault<scalar>(word("bucket" + Foam::name(k)), 0);
            }
        }
        else if (was.size())
        {
            Info<< type() << ' ' << name() << ": the impactor ("
                << impactor_->describe().c_str() << ") differs from the"
                << " restarted run's (" << was.c_str() << "): stages.dat"
                << " counts from this start" << endl;
        }
    }
}


void Foam::functionObjects::dpiEmittedDose::writeState()
{
    const FixedList<scalar*, 7> t(fields(total_));
    forAll(t, k)
    {
        setProperty(keys[k], *t[k]);
    }

    dictionary outlets;
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const labelList ids(patches_.sortedToc());
    forAll(ids, i)
    {
        // Scalars one by one: a list in the state is written at a lower
        // precision, and a restart would not go on with the same sums
        dictionary d;
        const FixedList<scalar*, 7> f(fields(perOutlet_[i]));
        forAll(f, k)
        {
            d.add(keys[k], *f[k]);
        }
        outlets.add(pbm[ids[i]].name(), d);
    }
    setProperty("outlets", outlets);

    setProperty("sizeClasses", sizeClasses_);
    dictionary bySize;
    forAll(bySize_, k)
    {
        bySize.add(word("class" + Foam::name(k)), bySize_[k]);
    }
    setProperty("bySize", bySize);

    if (impactor_.valid())
    {
        setProperty("impactor", impactor_->describe());
        dictionary byStage;
        forAll(byStage_, k)
        {
            byStage.add(word("bucket" + Foam::name(k)), byStage_[k]);
        }
        setProperty("byStage", byStage);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dpiEmittedDose::dpiEmittedDose
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "emittedDose", dict),
    cloudName_("dpiCloud"),
    patches_(),
    cutOff_(5e-6),
    shapeFactor_(1.15),
    sizeClasses_(),
    total_(),
    perOutlet_(),
    bySize_(),
    impactor_(),
    byStage_(),
    outletsFile_(),
    sizesFile_(),
    stagesFile_()
{
    read(dict);

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
        outletsFile_ = createFile("outlets");
        writeOutletsHeader(outletsFile_());
        sizesFile_ = createFile("sizes");
        writeSizesHeader(sizesFile_());
        if (impactor_.valid())
        {
            stagesFile_ = createFile("stages");
            writeStagesHeader(stagesFile_());
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::dpiEmittedDose::aerodynamicDiameter
(
    const dpiCloudInterface::escapedParcel& e,
    const scalar chi
)
{
    if (e.onCarrier)
    {
        return GREAT;
    }
    if (e.agglomerateParcels <= 1)
    {
        return e.d*sqrt(e.rho/rho0);
    }
    const scalar dv = cbrt(6*e.agglomerateVolume/constant::mathematical::pi);
    const scalar rhoAgg = e.agglomerateMass/e.agglomerateVolume;
    return dv*sqrt(rhoAgg/(chi*rho0));
}


Foam::scalar Foam::functionObjects::dpiEmittedDose::apiMass
(
    const dpiCloudInterface::escapedParcel& e
)
{
    return e.N*e.rho*constant::mathematical::pi/6*pow3(e.d);
}


bool Foam::functionObjects::dpiEmittedDose::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    // Parcels are counted as they leave: an execution skipped is a
    // fluid step's parcels lost to the count
    const word control(dict.lookupOrDefault<word>("executeControl", "timeStep"));
    const label interval(dict.lookupOrDefault<label>("executeInterval", 1));
    if (control != "timeStep" || interval != 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << " (dpiEmittedDose) counts"
            << " the parcels as they leave, so it executes at every time"
            << " step: executeControl " << control << ", executeInterval "
            << interval << " would miss the parcels that leave between"
            << " executions." << nl
            << "    Remove executeControl and executeInterval (the default"
            << " is every time step)." << exit(FatalIOError);
    }

    cloudName_ = dict.lookupOrDefault<word>("cloud", "dpiCloud");

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    patches_.clear();
    if (dict.found("patches"))
    {
        patches_ = devicePatches::select(pbm, dict, "patches", name());
    }
    else
    {
        for (label patchi = 0; patchi < pbm.nNonProcessor(); ++patchi)
        {
            patches_.insert(patchi);
        }
    }

    cutOff_ = dict.lookupOrDefault<scalar>("cutOff", 5e-6);
    shapeFactor_ = dict.lookupOrDefault<scalar>("shapeFactor", 1.15);
    // cutOff is an aerodynamic diameter in metres: 1 mm and up is no
    // particle of an inhaler (carriers are below 0.2 mm), but a diameter
    // typed in micrometres (cutOff 5), which would count every parcel fine
    if (!(cutOff_ > 0) || cutOff_ >= maxCutOff || shapeFactor_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": cutOff " << cutOff_
            << " [m] must be > 0 and below " << maxCutOff << " m, and"
            << " shapeFactor " << shapeFactor_ << " >= 1 (1 is a sphere)."
            << nl << "    cutOff is an aerodynamic diameter in metres: the"
            << " pharmacopoeia's 5 um is cutOff 5e-6" << exit(FatalIOError);
    }

    sizeClasses_ =
        dict.lookupOrDefault<labelList>("sizeClasses", labelList({1, 2, 4, 8, 16, 32}));
    forAll(sizeClasses_, k)
    {
        if (sizeClasses_[k] < 1 || (k && sizeClasses_[k] <= sizeClasses_[k-1]))
        {
            FatalIOErrorInFunction(dict)
                << "Function object " << name() << ": sizeClasses "
                << sizeClasses_ << " must be increasing numbers of API"
                << " primaries, from 1 (the upper bound of each class; the"
                << " default (1 2 4 8 16 32))." << exit(FatalIOError);
        }
    }

    impactor_.reset
    (
        dict.found("impactor")
      ? new impactorStages(dict.subDict("impactor"))
      : nullptr
    );

    // The totals so far, for the patches and classes now selected: those
    // of the run this one restarts, or of this run before a re-read
    readState();

    return true;
}


bool Foam::functionObjects::dpiEmittedDose::execute()
{
    const dpiCloudInterface& c =
        dpiCloudInterface::find(mesh_, cloudName_, name());
    const scalar pi6 = constant::mathematical::pi/6;

    // The parcels that left in the last fluid step: in total, per outlet
    // and by size
    const labelList ids(patches_.sortedToc());
    dose step;
    List<dose> stepPerOutlet(ids.size());
    scalarList stepBySize(bySize_.size(), Zero);
    scalarList stepByStage(byStage_.size(), Zero);
    for (const dpiCloudInterface::escapedParcel& e : c.escapedParcels())
    {
        if (!e.api)
        {
            continue;
        }
        const scalar m = apiMass(e);
        const label i = ids.find(e.patchi);
        if (i < 0)
        {
            step.elsewhere += m;
            continue;
        }
        const scalar dae = aerodynamicDiameter(e);
        const bool isFine = dae < cutOff_;
        if (impactor_.valid())
        {
            stepByStage[impactor_->bucket(dae, e.onCarrier)] += m;
        }
        step.add(m, e.N, e.onCarrier, e.agglomerateParcels, isFine);
        stepPerOutlet[i].add(m, e.N, e.onCarrier, e.agglomerateParcels, isFine);
        stepBySize
        [
            e.onCarrier
          ? bySize_.size() - 1
          : sizeClass(e.agglomerateParcels)
        ] += m;
    }

    // Into the totals, over all processors in one reduction (the step's
    // total, each outlet's, the size classes), and into the state written
    // with the time directories (a restart goes on counting)
    DynamicList<scalar> sums(toList(step));
    for (dose& d : stepPerOutlet)
    {
        sums.append(toList(d));
    }
    sums.append(stepBySize);
    sums.append(stepByStage);
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);
    label next = 0;
    auto addTo = [&sums, &next](dose& total)
    {
        for (scalar* t : fields(total))
        {
            *t += sums[next++];
        }
    };
    addTo(total_);
    for (dose& d : perOutlet_)
    {
        addTo(d);
    }
    for (scalar& m : bySize_)
    {
        m += sums[next++];
    }
    for (scalar& m : byStage_)
    {
        m += sums[next++];
    }
    writeState();

    // The API still in the domain
    dpiCloudInterface::parcelSamples p;
    c.samples(p);
    scalar inDomain = 0;
    forAll(p.N, i)
    {
        if (p.api[i])
        {
            inDomain += p.N[i]*p.rho[i]*pi6*pow3(p.d[i]);
        }
    }
    reduce(inDomain, sumOp<scalar>());
    const scalar loaded = inDomain + total_.emitted + total_.elsewhere;

    auto ratio = [](const scalar a, const scalar b)
    {
        return b > 0 ? a/b : 0;
    };

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << token::TAB << loaded
            << token::TAB << total_.emitted
            << token::TAB << total_.singlets
            << token::TAB << total_.agglomerates
            << token::TAB << total_.onCarriers
            << token::TAB << total_.fine
            << token::TAB << ratio(total_.fine, total_.emitted)
            << token::TAB << ratio(total_.fine, loaded)
            << token::TAB << total_.primaries
            << endl;

        OFstream& oos = outletsFile_();
        writeCurrentTime(oos);
        for (const dose& d : perOutlet_)
        {
            oos << token::TAB << d.emitted << token::TAB << d.singlets
                << token::TAB << d.agglomerates << token::TAB << d.onCarriers
                << token::TAB << d.fine;
        }
        oos << endl;

        OFstream& sos = sizesFile_();
        writeCurrentTime(sos);
        for (const scalar m : bySize_)
        {
            sos << token::TAB << m;
        }
        sos << endl;

        if (stagesFile_.valid())
        {
            scalar mmad, gsd;
            impactor_->mmadGsd(byStage_, mmad, gsd);
            OFstream& gos = stagesFile_();
            writeCurrentTime(gos);
            for (const scalar m : byStage_)
            {
                gos << token::TAB << m;
            }
            gos << token::TAB << mmad << token::TAB << gsd << endl;
        }
    }

    Log << type() << ' ' << name() << ": API emitted " << total_.emitted
        << " kg of " << loaded << " kg loaded (" << total_.primaries
        << " primaries; singlets " << total_.singlets << ", agglomerates "
        << total_.agglomerates << ", on carriers " << total_.onCarriers
        << "), fine " << total_.fine << " kg: FPF_emitted "
        << ratio(total_.fine, total_.emitted) << ", FPF_loaded "
        << ratio(total_.fine, loaded) << endl;

    return true;
}


bool Foam::functionObjects::dpiEmittedDose::write()
{
    return true;
}


bool Foam::functionObjects::dpiEmittedDose::end()
{
    Info<< type() << ' ' << name() << ": API emitted " << total_.emitted
        << " kg (singlets " << total_.singlets << ", agglomerates "
        << total_.agglomerates << ", on carriers " << total_.onCarriers
        << "), fine (d_ae < " << cutOff_ << " m) " << total_.fine
        << " kg" << endl;

    if (impactor_.valid())
    {
        scalar mmad, gsd;
        impactor_->mmadGsd(byStage_, mmad, gsd);
        const wordList names(impactor_->names());
        Info<< type() << ' ' << name() << ": "
            << impactor_->describe().c_str() << nl << "    API [kg]:";
        forAll(names, k)
        {
            Info<< ' ' << names[k] << ' ' << byStage_[k];
        }
        Info<< nl << "    MMAD " << mmad << " m, GSD " << gsd
            << " (of the stages; 0: not bracketed)" << endl;
    }
    return true;
}


// ************************************************************************* //
