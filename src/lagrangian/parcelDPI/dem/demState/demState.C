/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "demState.H"
#include "UIndirectList.H"
#include "scalarList.H"
#include "vectorList.H"

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


void Foam::demState::writeRows(Ostream& os, const labelUList& rows) const
{
    os  << List<point>(UIndirectList<point>(x, rows))
        << List<vector>(UIndirectList<vector>(v, rows))
        << List<vector>(UIndirectList<vector>(omega, rows))
        << List<scalar>(UIndirectList<scalar>(r, rows))
        << List<scalar>(UIndirectList<scalar>(m, rows))
        << List<scalar>(UIndirectList<scalar>(N, rows))
        << List<label>(UIndirectList<label>(typeId, rows))
        << List<label>(UIndirectList<label>(globalId, rows));
}


Foam::label Foam::demState::readRows(Istream& is)
{
    const List<point> xs(is);
    const List<vector> vs(is);
    const List<vector> omegas(is);
    const List<scalar> rs(is);
    const List<scalar> ms(is);
    const List<scalar> Ns(is);
    const labelList typeIds(is);
    const labelList globalIds(is);
    forAll(xs, k)
    {
        append
        (
            xs[k], vs[k], omegas[k], rs[k], ms[k], Ns[k], typeIds[k],
            globalIds[k]
        );
    }
    return xs.size();
}


// ************************************************************************* //
