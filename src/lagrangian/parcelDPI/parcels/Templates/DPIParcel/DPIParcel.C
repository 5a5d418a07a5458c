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
    while (td.keepParticle && !td.switchProcessor && this->stepFraction() < 1)
    {
        const scalar f = 1 - this->stepFraction();
        this->trackToAndHitFace(xDEM_ - this->position(), f, cloud, td);
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
