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
    total_()
{
    read(dict);

    // The totals of the run this one restarts (none at a first start)
    const FixedList<scalar*, 7> t(fields(total_));
    forAll(t, k)
    {
        *t[k] = getProperty<scalar>(keys[k], 0);
    }

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::functionObjects::dpiEmittedDose::aerodynamicDiameter
(
    const dpiCloudInterface::escapedParcel& e
) const
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
    return dv*sqrt(rhoAgg/(shapeFactor_*rho0));
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
    if (cutOff_ <= 0 || shapeFactor_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": cutOff " << cutOff_
            << " [m] must be > 0 and shapeFactor " << shapeFactor_
            << " >= 1 (1 is a sphere)." << exit(FatalIOError);
    }

    return true;
}


bool Foam::functionObjects::dpiEmittedDose::execute()
{
    const dpiCloudInterface& c =
        dpiCloudInterface::find(mesh_, cloudName_, name());
    const scalar pi6 = constant::mathematical::pi/6;

    // The parcels that left in the last fluid step
    dose step;
    for (const dpiCloudInterface::escapedParcel& e : c.escapedParcels())
    {
        if (!e.api)
        {
            continue;
        }
        const scalar m = e.N*e.rho*pi6*pow3(e.d);
        if (!patches_.found(e.patchi))
        {
            step.elsewhere += m;
            continue;
        }
        step.emitted += m;
        step.primaries += e.N;
        if (e.onCarrier)
        {
            step.onCarriers += m;
        }
        else if (e.agglomerateParcels <= 1)
        {
            step.singlets += m;
        }
        else
        {
            step.agglomerates += m;
        }
        if (aerodynamicDiameter(e) < cutOff_)
        {
            step.fine += m;
        }
    }

    // Into the totals, over all processors, and into the state written
    // with the time directories (a restart goes on counting)
    const FixedList<scalar*, 7> s(fields(step));
    const FixedList<scalar*, 7> t(fields(total_));
    forAll(t, k)
    {
        reduce(*s[k], sumOp<scalar>());
        *t[k] += *s[k];
        setProperty(keys[k], *t[k]);
    }

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
    return true;
}


// ************************************************************************* //
