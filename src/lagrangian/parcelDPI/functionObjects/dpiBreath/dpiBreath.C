/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiBreath.H"
#include "fvMesh.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "IOdictionary.H"
#include "devicePatches.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dpiBreath, 0);
    addToRunTimeSelectionTable(functionObject, dpiBreath, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::functionObjects::dpiBreath::inletSetting() const
{
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    const volScalarField& p = mesh_.lookupObject<volScalarField>(pName_);

    // The conditions of the inlet's first patch (the others alike)
    const label patchi = inlet_.sortedToc().first();
    const word uType(U.boundaryField()[patchi].type());
    const word pType(p.boundaryField()[patchi].type());

    string what;
    if (uType == "flowRateInletVelocity")
    {
        what = "the flow rate";
    }
    else if (pType == "totalPressure")
    {
        what = "the pressure drop (total pressure at the inlet)";
    }
    else if (uType == "fixedValue" || uType == "uniformFixedValue")
    {
        what = "the velocity";
    }
    else
    {
        what = "neither flow rate, pressure nor velocity alone";
    }
    return
        what + " (" + mesh_.boundaryMesh()[patchi].name() + ": "
      + UName_ + " " + uType + ", " + pName_ + " " + pType + ")";
}


Foam::functionObjects::dpiBreath::side
Foam::functionObjects::dpiBreath::sum(const labelHashSet& patchIds) const
{
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    const volScalarField& p = mesh_.lookupObject<volScalarField>(pName_);
    const surfaceScalarField& phi =
        mesh_.lookupObject<surfaceScalarField>(phiName_);

    side s;
    scalar pA = 0;
    scalar p0Flux = 0;
    for (const label patchi : patchIds)
    {
        const scalarField& mag = mesh_.magSf().boundaryField()[patchi];
        const scalarField& pp = p.boundaryField()[patchi];
        const vectorField& Up = U.boundaryField()[patchi];
        const scalarField& phip = phi.boundaryField()[patchi];

        s.flux += gSum(phip);
        s.area += gSum(mag);
        pA += gSum(pp*mag);
        p0Flux += gSum((pp + 0.5*magSqr(Up))*phip);
    }
    s.p = s.area > 0 ? pA/s.area : 0;
    s.p0 = mag(s.flux) > VSMALL ? p0Flux/s.flux : s.p;
    return s;
}


void Foam::functionObjects::dpiBreath::start()
{
    if (rho_ <= 0)
    {
        const word rhoName("rho." + phase_);
        // The uniform density field dpiFoam registers; a processor
        // without cells reads it from the others
        const volScalarField* rho =
            mesh_.cfindObject<volScalarField>(rhoName);
        rho_ = (rho && rho->size()) ? rho->primitiveField().first() : -1;
        reduce(rho_, maxOp<scalar>());
        if (rho_ <= 0)
        {
            FatalErrorInFunction
                << "Function object " << name() << ": no gas density: no"
                << " field " << rhoName << " (phase " << phase_ << ")."
                << nl << "    Give `rho` [kg/m3] or the gas `phase`."
                << exit(FatalError);
        }
    }

    inletSets_ = inletSetting();
    Info<< type() << ' ' << name() << ": the inlet sets " << inletSets_.c_str()
        << "; Q in L/min, pressure drops in Pa (rho " << rho_ << " kg/m3)"
        << endl;

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
    }
    started_ = true;
}


void Foam::functionObjects::dpiBreath::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Breath through the device");
    writeHeaderValue(os, "the inlet sets", inletSets_.c_str());
    writeHeaderValue(os, "gas density [kg/m3]", rho_);
    writeHeader
    (
        os,
        "Q [L/min] into the inlet and out of the outlet; dp = rho (in - out)"
        " [Pa]: static (area-averaged p), total (flux-weighted p + |U|^2/2);"
        " U_in = Q_in/A_in [m/s]"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "Q_in");
    writeTabbed(os, "Q_out");
    writeTabbed(os, "dp_static");
    writeTabbed(os, "dp_total");
    writeTabbed(os, "U_in");
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dpiBreath::dpiBreath
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "breath", dict),
    inlet_(),
    outlet_(),
    UName_(),
    phiName_(),
    pName_(),
    rho_(-1),
    phase_(),
    inletSets_(),
    started_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dpiBreath::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    inlet_ = devicePatches::select(pbm, dict, "inlet", name());
    outlet_ = devicePatches::select(pbm, dict, "outlet", name());

    // The gas phase: the key, else transportProperties' continuousPhase
    // (dpiFoam's), else air
    word phase("air");
    if (!dict.readIfPresent("phase", phase))
    {
        IOdictionary transport
        (
            IOobject
            (
                "transportProperties",
                mesh_.time().constant(),
                mesh_,
                IOobject::READ_IF_PRESENT,
                IOobject::NO_WRITE,
                false
            )
        );
        transport.readIfPresent("continuousPhase", phase);
    }
    phase_ = phase;
    UName_ = dict.lookupOrDefault<word>("U", "U." + phase_);
    phiName_ = dict.lookupOrDefault<word>("phi", "phi." + phase_);
    pName_ = dict.lookupOrDefault<word>("p", "p");

    rho_ = dict.lookupOrDefault<scalar>("rho", -1);
    if (dict.found("rho") && rho_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name() << ": rho " << rho_
            << " [kg/m3] must be > 0." << exit(FatalIOError);
    }

    return true;
}


bool Foam::functionObjects::dpiBreath::execute()
{
    // A run without a gas (DEM only: the inhaler's sedimentation) has no
    // breath to measure
    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        if (!started_)
        {
            Info<< type() << ' ' << name() << ": no gas field " << UName_
                << " in this run: nothing to measure" << endl;
            started_ = true;
        }
        return true;
    }
    if (!started_ || inletSets_.empty())
    {
        start();
    }

    const side in(sum(inlet_));
    const side out(sum(outlet_));

    // L/min from m3/s; the inlet's outward flux is negative when the gas
    // comes in
    const scalar Qin = -in.flux*6e4;
    const scalar Qout = out.flux*6e4;
    const scalar dpStatic = rho_*(in.p - out.p);
    const scalar dpTotal = rho_*(in.p0 - out.p0);
    const scalar Uin = in.area > 0 ? -in.flux/in.area : 0;

    Log << type() << ' ' << name() << ": Q in " << Qin << " L/min, out "
        << Qout << " L/min; pressure drop static " << dpStatic
        << " Pa, total " << dpTotal << " Pa" << endl;

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        writeCurrentTime(os);
        os  << token::TAB << Qin
            << token::TAB << Qout
            << token::TAB << dpStatic
            << token::TAB << dpTotal
            << token::TAB << Uin
            << endl;
    }
    return true;
}


bool Foam::functionObjects::dpiBreath::write()
{
    return true;
}


// ************************************************************************* //
