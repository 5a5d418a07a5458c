/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "DPIParcel.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "transform.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::DPIParcel<ParcelType>::DPIParcel(const DPIParcel<ParcelType>& p)
:
    ParcelType(p),
    omega_(p.omega_),
    xDEM_(p.xDEM_),
    f_(p.f_),
    torque_(p.torque_),
    globalId_(p.globalId_),
    agglomerateId_(p.agglomerateId_),
    contactKeys_(p.contactKeys_),
    contactXi_(p.contactXi_)
{}


template<class ParcelType>
Foam::DPIParcel<ParcelType>::DPIParcel
(
    const DPIParcel<ParcelType>& p,
    const polyMesh& mesh
)
:
    ParcelType(p, mesh),
    omega_(p.omega_),
    xDEM_(p.xDEM_),
    f_(p.f_),
    torque_(p.torque_),
    globalId_(p.globalId_),
    agglomerateId_(p.agglomerateId_),
    contactKeys_(p.contactKeys_),
    contactXi_(p.contactXi_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::DPIParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar
)
{
    td.switchProcessor = false;
    td.keepParticle = true;

    // Re-entered after every processor-transfer round (Cloud::move): the
    // loop condition makes a finished parcel (stepFraction 1) do nothing.
    //
    // The displacement to the DEM position is taken once per call and its
    // remaining share tracked, as the stock KinematicParcel tracks a fixed
    // f*s. Re-aimed after every face (xDEM - position()), a parcel moving
    // within a mesh face's plane bounced between the two cells for ever:
    // position() rounds differently in each cell, the new aim points into
    // the face from both sides, and the track hits it at zero fraction
    // (a parcel on x = 3e-3 of case1ParticleWall; 100,000 parcels on a
    // lattice through mesh faces)
    const scalar f0 = 1 - this->stepFraction();
    const vector s(xDEM_ - this->position());
    label nStuck = 0;
    const label maxStuckFaces = 1000;   // a parcel crosses a few per step
    while (td.keepParticle && !td.switchProcessor && this->stepFraction() < 1)
    {
        const scalar f = 1 - this->stepFraction();
        this->trackToAndHitFace((f/f0)*s, f, cloud, td);

        // Safety net: a track that makes no progress for many faces ends
        // here; the DEM position stays the parcel's (xDEM_), the mesh
        // position is the one the tracking reached
        if (1 - this->stepFraction() < f)
        {
            nStuck = 0;
        }
        else if (++nStuck > maxStuckFaces)
        {
            this->stepFraction() = 1;
        }
    }

    return td.keepParticle;
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::DPIParcel<ParcelType>::hitPatch
(
    TrackCloudType& cloud,
    trackingData& td
)
{
    const polyPatch& pp = this->mesh().boundaryMesh()[this->patch()];

    cloud.functions().postPatch(*this, pp, td.keepParticle);

    if (isA<processorPolyPatch>(pp) || polyPatch::constraintType(pp.type()))
    {
        // Processor transfer and constraint patches: default dispatch
        return false;
    }

    if (isA<wallPolyPatch>(pp))
    {
        // The DEM has handled the wall contact; a DEM position beyond the
        // wall face by less than a radius is a parcel in wall overlap: end
        // the track here and keep the DEM position authoritative. Beyond
        // a radius the parcel has passed through the wall (the patch is not
        // a DEM wall, or the DEM step is far too large): it is lost.
        const label facei = this->face();
        const vector nf = normalised(this->mesh().faceAreas()[facei]);
        const scalar s = (xDEM_ - this->mesh().faceCentres()[facei]) & nf;

        if (s > 0.5*this->d())
        {
            cloud.recordLostParcel(*this, pp);
            td.keepParticle = false;
        }
        else
        {
            this->stepFraction() = 1;
        }
        return true;
    }

    // Open patch (outlet, inlet): the parcel leaves the domain
    cloud.recordEscapedParcel(*this, pp);
    td.keepParticle = false;
    return true;
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::DPIParcel<ParcelType>::hitProcessorPatch
(
    TrackCloudType&,
    trackingData& td
)
{
    td.switchProcessor = true;
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::DPIParcel<ParcelType>::hitWallPatch
(
    TrackCloudType&,
    trackingData&
)
{
    // Handled in hitPatch
    this->stepFraction() = 1;
}


template<class ParcelType>
void Foam::DPIParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);

    omega_ = transform(T, omega_);
    xDEM_ = transform(T, xDEM_);
    f_ = transform(T, f_);
    torque_ = transform(T, torque_);
    contactXi_ = transform(T, contactXi_);
}


template<class ParcelType>
void Foam::DPIParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);

    xDEM_ += separation;
}


// * * * * * * * * * * * * * * * * IOStream operators * * * * * * * * * * * //

#include "DPIParcelIO.C"

// ************************************************************************* //
