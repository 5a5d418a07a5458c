/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiFPF.H"
#include "dpiCloudInterface.H"
#include "agglomerateTracker.H"
#include "fvMesh.H"
#include "cloud.H"
#include "Map.H"
#include "PstreamCombineReduceOps.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dpiFPF, 0);
    addToRunTimeSelectionTable(functionObject, dpiFPF, dictionary);

    // The name that says what it measures: the FPF in a sampling box (the
    // user guide's), beside the emitted dose's aerodynamic FPF
    // (dpiEmittedDose)
    addNamedToRunTimeSelectionTable
    (
        functionObject,
        dpiFPF,
        dictionary,
        dpiBoxFPF
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dpiFPF::checkBox(const dictionary& dict) const
{
    // Bounds of the whole mesh (reduced over processors)
    const boundBox meshBb(mesh_.points(), true);

    if (!box_.valid() || cmptMin(box_.span()) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": the sampling box "
            << box_.min() << ' ' << box_.max() << " is empty: give"
            << " `box (min) (max);` with min < max in x, y and z [m]"
            << exit(FatalIOError);
    }

    if (!meshBb.overlaps(box_))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": the sampling box "
            << box_.min() << ' ' << box_.max()
            << " lies outside the domain (mesh bounds "
            << meshBb.min() << ' ' << meshBb.max() << ")." << nl
            << "    Give the box in metres, inside the mesh."
            << exit(FatalIOError);
    }

    boundBox grown(meshBb);
    grown.inflate(1e-6);
    if (!grown.contains(box_.min()) || !grown.contains(box_.max()))
    {
        WarningInFunction
            << "Function object " << name() << ": the sampling box "
            << box_.min() << ' ' << box_.max()
            << " sticks out of the mesh bounds "
            << meshBb.min() << ' ' << meshBb.max()
            << " (accepted: only its part inside the domain can hold"
            << " parcels)" << endl;
    }
}


void Foam::functionObjects::dpiFPF::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Fine particle fraction of cloud " + cloudName_);
    writeHeaderValue(os, "box min", box_.min());
    writeHeaderValue(os, "box max", box_.max());
    writeHeader
    (
        os,
        "Primaries (sum of N over API parcels); singlet = API parcel alone"
        " in its agglomerate"
    );
    writeHeader
    (
        os,
        "FPF_box = singletsBox/apiBox, FPF_system = singletsBox/apiSystem;"
        " *_acc: sums over the samples so far"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "apiSystem");
    writeTabbed(os, "apiBox");
    writeTabbed(os, "singletsBox");
    writeTabbed(os, "FPF_box");
    writeTabbed(os, "FPF_system");
    writeTabbed(os, "FPF_box_acc");
    writeTabbed(os, "FPF_system_acc");
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dpiFPF::dpiFPF
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "fpf", dict),
    cloudName_("dpiCloud"),
    box_(),
    sum_(),
    nSamples_(0)
{
    read(dict);

    // The sums of the run this one restarts (none at a first start)
    sum_.apiSystem = getProperty<scalar>("apiSystemSum", 0);
    sum_.apiBox = getProperty<scalar>("apiBoxSum", 0);
    sum_.singletsBox = getProperty<scalar>("singletsBoxSum", 0);
    nSamples_ = getProperty<label>("nSamples", 0);

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::functionObjects::dpiFPF::sample
Foam::functionObjects::dpiFPF::count() const
{
    dpiCloudInterface::parcelSamples s;
    dpiCloudInterface::find(mesh_, cloudName_, name()).samples(s);

    // A singlet is an API parcel that is the only member of its agglomerate
    const Map<label> members(agglomerateTracker::members(s.agglomerateId));

    sample r;
    forAll(s.position, i)
    {
        if (!s.api[i])
        {
            continue;
        }
        r.apiSystem += s.N[i];

        if (box_.contains(s.position[i]))
        {
            r.apiBox += s.N[i];
            if (members[s.agglomerateId[i]] == 1)
            {
                r.singletsBox += s.N[i];
            }
        }
    }

    reduce(r.apiSystem, sumOp<scalar>());
    reduce(r.apiBox, sumOp<scalar>());
    reduce(r.singletsBox, sumOp<scalar>());

    return r;
}


bool Foam::functionObjects::dpiFPF::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "dpiCloud");

    if (!dict.found("box"))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": missing `box (min) (max);`"
            << " (the sampling box, metres)" << exit(FatalIOError);
    }
    dict.readEntry("box", box_);

    checkBox(dict);

    return true;
}


bool Foam::functionObjects::dpiFPF::execute()
{
    const sample r = count();

    sum_.apiSystem += r.apiSystem;
    sum_.apiBox += r.apiBox;
    sum_.singletsBox += r.singletsBox;
    ++nSamples_;

    // Into the state written with the time directories, for a restart
    setProperty("apiSystemSum", sum_.apiSystem);
    setProperty("apiBoxSum", sum_.apiBox);
    setProperty("singletsBoxSum", sum_.singletsBox);
    setProperty("nSamples", nSamples_);

    auto ratio = [](const scalar a, const scalar b)
    {
        return b > 0 ? a/b : 0;
    };

    const scalar fpfBox = ratio(r.singletsBox, r.apiBox);
    const scalar fpfSystem = ratio(r.singletsBox, r.apiSystem);

    Log << type() << ' ' << name() << ": API primaries in system "
        << r.apiSystem << ", in box " << r.apiBox << ", singlets in box "
        << r.singletsBox << ": FPF_box " << fpfBox << ", FPF_system "
        << fpfSystem << endl;

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << token::TAB << r.apiSystem
            << token::TAB << r.apiBox
            << token::TAB << r.singletsBox
            << token::TAB << fpfBox
            << token::TAB << fpfSystem
            << token::TAB << ratio(sum_.singletsBox, sum_.apiBox)
            << token::TAB << ratio(sum_.singletsBox, sum_.apiSystem)
            << endl;
    }

    return true;
}


bool Foam::functionObjects::dpiFPF::write()
{
    return true;
}


bool Foam::functionObjects::dpiFPF::end()
{
    if (nSamples_)
    {
        Info<< type() << ' ' << name() << ": accumulated over " << nSamples_
            << " samples: FPF_box "
            << (sum_.apiBox > 0 ? sum_.singletsBox/sum_.apiBox : 0)
            << ", FPF_system "
            << (sum_.apiSystem > 0 ? sum_.singletsBox/sum_.apiSystem : 0)
            << endl;
    }
    return true;
}


// ************************************************************************* //
