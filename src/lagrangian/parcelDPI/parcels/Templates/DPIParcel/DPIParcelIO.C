/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
-------------------------------------------------------------------------------
    Every field appears in: the Istream constructor (ASCII, non-native and
    native binary), operator<<, readFields/writeFields, readObjects/
    writeObjects and transformProperties. A field missing in one of them is
    silently reset on processor transfer, restart or in VTK output.
\*---------------------------------------------------------------------------*/

#include "DPIParcel.H"
#include "IOstreams.H"
#include "IOField.H"
#include "labelFieldIOField.H"
#include "vectorFieldIOField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::DPIParcel<ParcelType>::propertyList_ =
    Foam::DPIParcel<ParcelType>::propertyList();

template<class ParcelType>
const std::size_t Foam::DPIParcel<ParcelType>::sizeofFields
(
    offsetof(DPIParcel<ParcelType>, contactKeys_)
  - offsetof(DPIParcel<ParcelType>, omega_)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::DPIParcel<ParcelType>::DPIParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    omega_(Zero),
    xDEM_(Zero),
    f_(Zero),
    torque_(Zero),
    globalId_(-1),
    agglomerateId_(-1),
    contactKeys_(),
    contactXi_()
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is  >> omega_ >> xDEM_ >> f_ >> torque_
                >> globalId_ >> agglomerateId_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size: component by component
            is.beginRawRead();
            readRawScalar(is, omega_.data(), vector::nComponents);
            readRawScalar(is, xDEM_.data(), vector::nComponents);
            readRawScalar(is, f_.data(), vector::nComponents);
            readRawScalar(is, torque_.data(), vector::nComponents);
            readRawLabel(is, &globalId_);
            readRawLabel(is, &agglomerateId_);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&omega_), sizeofFields);
        }

        is  >> contactKeys_ >> contactXi_;
    }
    else
    {
        xDEM_ = this->position();
    }

    is.check(FUNCTION_NAME);
}


template<class ParcelType>
template<class CloudType>
void Foam::DPIParcel<ParcelType>::readFields(CloudType& c)
{
    const bool valid = c.size();

    ParcelType::readFields(c);

    IOField<vector> omega(c.fieldIOobject("omega", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, omega);

    IOField<vector> xDEM(c.fieldIOobject("xDEM", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, xDEM);

    IOField<vector> f(c.fieldIOobject("f", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, f);

    IOField<vector> torque
    (
        c.fieldIOobject("torque", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, torque);

    IOField<label> globalId
    (
        c.fieldIOobject("globalId", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, globalId);

    IOField<label> agglomerateId
    (
        c.fieldIOobject("agglomerateId", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, agglomerateId);

    labelFieldCompactIOField contactKeys
    (
        c.fieldIOobject("contactKeys", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, contactKeys);

    vectorFieldCompactIOField contactXi
    (
        c.fieldIOobject("contactXi", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, contactXi);

    label i = 0;
    for (DPIParcel<ParcelType>& p : c)
    {
        p.omega_ = omega[i];
        p.xDEM_ = xDEM[i];
        p.f_ = f[i];
        p.torque_ = torque[i];
        p.globalId_ = globalId[i];
        p.agglomerateId_ = agglomerateId[i];
        p.contactKeys_ = contactKeys[i];
        p.contactXi_ = contactXi[i];
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::DPIParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;

    IOField<vector> omega(c.fieldIOobject("omega", IOobject::NO_READ), np);
    IOField<vector> xDEM(c.fieldIOobject("xDEM", IOobject::NO_READ), np);
    IOField<vector> f(c.fieldIOobject("f", IOobject::NO_READ), np);
    IOField<vector> torque(c.fieldIOobject("torque", IOobject::NO_READ), np);
    IOField<label> globalId
    (
        c.fieldIOobject("globalId", IOobject::NO_READ),
        np
    );
    IOField<label> agglomerateId
    (
        c.fieldIOobject("agglomerateId", IOobject::NO_READ),
        np
    );
    labelFieldCompactIOField contactKeys
    (
        c.fieldIOobject("contactKeys", IOobject::NO_READ),
        np
    );
    vectorFieldCompactIOField contactXi
    (
        c.fieldIOobject("contactXi", IOobject::NO_READ),
        np
    );

    label i = 0;
    for (const DPIParcel<ParcelType>& p : c)
    {
        omega[i] = p.omega_;
        xDEM[i] = p.xDEM_;
        f[i] = p.f_;
        torque[i] = p.torque_;
        globalId[i] = p.globalId_;
        agglomerateId[i] = p.agglomerateId_;
        contactKeys[i] = p.contactKeys_;
        contactXi[i] = p.contactXi_;
        ++i;
    }

    omega.write(valid);
    xDEM.write(valid);
    f.write(valid);
    torque.write(valid);
    globalId.write(valid);
    agglomerateId.write(valid);
    contactKeys.write(valid);
    contactXi.write(valid);
}


template<class ParcelType>
void Foam::DPIParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);

    #undef  writeProp
    #define writeProp(Name, Value)                                            \
        ParcelType::writeProperty(os, Name, Value, namesOnly, delim, filters)

    writeProp("omega", omega_);
    writeProp("xDEM", xDEM_);
    writeProp("f", f_);
    writeProp("torque", torque_);
    writeProp("globalId", globalId_);
    writeProp("agglomerateId", agglomerateId_);

    #undef writeProp
}


template<class ParcelType>
template<class CloudType>
void Foam::DPIParcel<ParcelType>::readObjects
(
    CloudType& c,
    const objectRegistry& obr
)
{
    ParcelType::readObjects(c, obr);

    if (!c.size()) return;

    const auto& omega = cloud::lookupIOField<vector>("omega", obr);
    const auto& xDEM = cloud::lookupIOField<vector>("xDEM", obr);
    const auto& f = cloud::lookupIOField<vector>("f", obr);
    const auto& torque = cloud::lookupIOField<vector>("torque", obr);
    const auto& globalId = cloud::lookupIOField<label>("globalId", obr);
    const auto& agglomerateId =
        cloud::lookupIOField<label>("agglomerateId", obr);

    label i = 0;
    for (DPIParcel<ParcelType>& p : c)
    {
        p.omega_ = omega[i];
        p.xDEM_ = xDEM[i];
        p.f_ = f[i];
        p.torque_ = torque[i];
        p.globalId_ = globalId[i];
        p.agglomerateId_ = agglomerateId[i];
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::DPIParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();

    auto& omega = cloud::createIOField<vector>("omega", np, obr);
    auto& xDEM = cloud::createIOField<vector>("xDEM", np, obr);
    auto& f = cloud::createIOField<vector>("f", np, obr);
    auto& torque = cloud::createIOField<vector>("torque", np, obr);
    auto& globalId = cloud::createIOField<label>("globalId", np, obr);
    auto& agglomerateId =
        cloud::createIOField<label>("agglomerateId", np, obr);

    label i = 0;
    for (const DPIParcel<ParcelType>& p : c)
    {
        omega[i] = p.omega_;
        xDEM[i] = p.xDEM_;
        f[i] = p.f_;
        torque[i] = p.torque_;
        globalId[i] = p.globalId_;
        agglomerateId[i] = p.agglomerateId_;
        ++i;
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const DPIParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.omega_
            << token::SPACE << p.xDEM_
            << token::SPACE << p.f_
            << token::SPACE << p.torque_
            << token::SPACE << p.globalId_
            << token::SPACE << p.agglomerateId_;
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.omega_),
            DPIParcel<ParcelType>::sizeofFields
        );
    }

    os  << token::SPACE << p.contactKeys_
        << token::SPACE << p.contactXi_;

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
