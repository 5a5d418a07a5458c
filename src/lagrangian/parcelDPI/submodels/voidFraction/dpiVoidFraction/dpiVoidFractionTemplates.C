/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiVoidFraction.H"
#include "volFields.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "dpiRemotePoints.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::tmp<Foam::volScalarField>
Foam::dpiVoidFraction::theta(const CloudType& cloud) const
{
    typedef typename CloudType::parcelType parcelType;

    const fvMesh& mesh = cloud.mesh();

    tmp<volScalarField> ttheta
    (
        new volScalarField
        (
            IOobject
            (
                cloud.name() + ":theta",
                mesh.time().timeName(),
                cloud.db(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh,
            dimensionedScalar(dimless, Zero),
            extrapolatedCalculatedFvPatchScalarField::typeName
        )
    );
    volScalarField& theta = ttheta.ref();
    scalarField& Vs = theta.primitiveFieldRef();

    if (!Pstream::parRun())
    {
        for (const parcelType& p : cloud)
        {
            distribute
            (
                mesh, p.position(), p.cell(), 0.5*p.d(),
                solidVolume(p.d(), p.N()), Vs
            );
        }
    }
    else
    {
        // Points in another processor's sub-domain go to its cells, as in
        // the serial run; points outside the mesh to the centre's cell
        DynamicList<label> cells;
        DynamicList<scalar> weights;
        DynamicList<point> unresolved;
        DynamicList<point> remotePts;
        DynamicList<scalar> remoteVs;
        DynamicList<label> remoteOwnCell;

        for (const parcelType& p : cloud)
        {
            const scalar Vp = solidVolume(p.d(), p.N());
            pointWeights
            (
                mesh, p.position(), p.cell(), 0.5*p.d(), cells, weights,
                &unresolved
            );
            forAll(cells, k)
            {
                Vs[cells[k]] += weights[k]*Vp;
            }
            for (const point& pt : unresolved)
            {
                remotePts.append(pt);
                remoteVs.append(Vp/nPoints);
                remoteOwnCell.append(p.cell());
            }
        }

        const dpiRemotePoints remote(mesh, remotePts);
        remote.add(remoteVs, Vs);
        forAll(remotePts, k)
        {
            if (!remote.found(k))
            {
                Vs[remoteOwnCell[k]] += remoteVs[k];
            }
        }
    }

    // The solid volume the gas's floor will not see
    scalar clipped = 0;
    forAll(Vs, celli)
    {
        clipped += max(Vs[celli] - (1 - alphaMin_)*mesh.V()[celli], 0);
    }
    reduce(clipped, sumOp<scalar>());
    if (clipped > 0)
    {
        Info<< "    Void fraction: floor alphaMin " << alphaMin_
            << " clips a solid volume of " << clipped << " m^3 ("
            << clipped/max(gSum(Vs), VSMALL) << " of the total)" << endl;
    }

    Vs /= mesh.V();
    theta.correctBoundaryConditions();

    return ttheta;
}


// ************************************************************************* //
