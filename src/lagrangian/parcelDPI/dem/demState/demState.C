/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
\*---------------------------------------------------------------------------*/

#include "demState.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demState::clear()
{
    x.clear();
    v.clear();
    omega.clear();
    r.clear();
    m.clear();
    N.clear();
    typeId.clear();
    globalId.clear();
    fExt.clear();
    f.clear();
    torque.clear();
    fContact.clear();
    tContact.clear();
    contactForcesValid = false;
    nOwned = -1;
}


Foam::label Foam::demState::append
(
    const point& xi,
    const vector& vi,
    const vector& omegai,
    const scalar ri,
    const scalar mi,
    const scalar Ni,
    const label typei,
    const label globalIdi
)
{
    x.append(xi);
    v.append(vi);
    omega.append(omegai);
    r.append(ri);
    m.append(mi);
    N.append(Ni);
    typeId.append(typei);
    globalId.append(globalIdi);
    fExt.append(Zero);
    f.append(Zero);
    torque.append(Zero);
    fContact.append(Zero);
    tContact.append(Zero);
    return x.size() - 1;
}


// ************************************************************************* //
