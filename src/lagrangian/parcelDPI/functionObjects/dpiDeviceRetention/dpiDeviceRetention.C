/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiDeviceRetention.H"
#include "fvMesh.H"
#include "wallPolyPatch.H"
#include "Map.H"
#include "HashOps.H"
#include "mathematicalConstants.H"
#include "dpiCloudInterface.H"
#include "devicePatches.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(dpiDeviceRetention, 0);
    addToRunTimeSelectionTable(functionObject, dpiDeviceRetention, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::dpiDeviceRetention::writeFileHeader(Ostream& os)
{
    writeHeader(os, "API retained in the device, cloud " + cloudName_);
    writeHeader
    (
        os,
        "API masses [kg] in the domain: inDevice = onCarriers + neither +"
        " the deposits on the wall patches"
    );
    writeCommented(os, "Time");
    writeTabbed(os, "inDevice");
    writeTabbed(os, "onCarriers");
    writeTabbed(os, "neither");
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (const label patchi : patches_)
    {
        writeTabbed(os, pbm[patchi].name());
    }
    os  << endl;
}


Foam::label Foam::functionObjects::dpiDeviceRetention::touchedPatch
(
    const point& x,
    const scalar r,
    const label celli
) const
{
    if (celli < 0)
    {
        return -1;
    }
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    label touched = -1;
    for (const label facei : mesh_.cells()[celli])
    {
        if (mesh_.isInternalFace(facei))
        {
            continue;
        }
        const label patchi = pbm.whichPatch(facei);
        if (!patches_.found(patchi) || (touched >= 0 && patchi >= touched))
        {
            continue;
        }
        const pointHit h =
            mesh_.faces()[facei].nearestPoint(x, mesh_.points());
        if (h.distance() < r)
        {
            touched = patchi;
        }
    }
    return touched;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::dpiDeviceRetention::dpiDeviceRetention
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "retention", dict),
    cloudName_("dpiCloud"),
    patches_()
{
    read(dict);

    if (Pstream::master() && writeToFile())
    {
        writeFileHeader(file());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::dpiDeviceRetention::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    cloudName_ = dict.lookupOrDefault<word>("cloud", "dpiCloud");

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    if (dict.found("patches"))
    {
        patches_ = devicePatches::select(pbm, dict, "patches", name()).sortedToc();
    }
    else
    {
        DynamicList<label> walls;
        for (label patchi = 0; patchi < pbm.nNonProcessor(); ++patchi)
        {
            if (isA<wallPolyPatch>(pbm[patchi]))
            {
                walls.append(patchi);
            }
        }
        patches_.transfer(walls);
    }

    return true;
}


bool Foam::functionObjects::dpiDeviceRetention::execute()
{
    dpiCloudInterface::parcelSamples p;
    dpiCloudInterface::find(mesh_, cloudName_, name()).samples(p);
    const scalar pi6 = constant::mathematical::pi/6;

    // The agglomerates that hold a carrier, and those off carriers that
    // touch a wall patch (the lowest patch index), over all processors:
    // an agglomerate may be split between them
    labelHashSet carried;
    Map<label> deposited;
    forAll(p.N, i)
    {
        if (!p.api[i])
        {
            carried.insert(p.agglomerateId[i]);
        }
    }
    Pstream::combineGather(carried, HashSetOps::plusEqOp<label, Hash<label>>());
    Pstream::combineScatter(carried);

    forAll(p.N, i)
    {
        if (p.api[i] && !carried.found(p.agglomerateId[i]))
        {
            const label patchi =
                touchedPatch(p.position[i], p.d[i]/2, p.cell[i]);
            if (patchi >= 0)
            {
                auto iter = deposited.find(p.agglomerateId[i]);
                if (!iter.found())
                {
                    deposited.insert(p.agglomerateId[i], patchi);
                }
                else if (patchi < *iter)
                {
                    *iter = patchi;
                }
            }
        }
    }
    Pstream::mapCombineGather(deposited, minEqOp<label>());
    Pstream::mapCombineScatter(deposited);

    // The API masses: in the device, on carriers, per wall patch
    scalarList m(3 + patches_.size(), Zero);
    forAll(p.N, i)
    {
        if (!p.api[i])
        {
            continue;
        }
        const scalar mi = p.N[i]*p.rho[i]*pi6*pow3(p.d[i]);
        m[0] += mi;
        if (carried.found(p.agglomerateId[i]))
        {
            m[1] += mi;
            continue;
        }
        const auto iter = deposited.cfind(p.agglomerateId[i]);
        if (iter.found())
        {
            m[3 + patches_.find(*iter)] += mi;
        }
        else
        {
            m[2] += mi;
        }
    }
    Pstream::listCombineGather(m, plusEqOp<scalar>());

    if (Pstream::master())
    {
        if (writeToFile())
        {
            OFstream& os = file();
            writeCurrentTime(os);
            for (const scalar mk : m)
            {
                os  << token::TAB << mk;
            }
            os  << endl;
        }

        scalar onWalls = 0;
        for (label k = 3; k < m.size(); ++k)
        {
            onWalls += m[k];
        }
        Log << type() << ' ' << name() << ": API in the device " << m[0]
            << " kg: on carriers " << m[1] << ", on the walls " << onWalls
            << ", neither " << m[2] << endl;
    }

    return true;
}


bool Foam::functionObjects::dpiDeviceRetention::write()
{
    return true;
}


// ************************************************************************* //
