/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiFluidForce.H"
#include "dictKeys.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dpiFluidForce, 0);
    defineRunTimeSelectionTable(dpiFluidForce, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dpiFluidForce::dpiFluidForce
(
    const word& name,
    const dictionary& coeffs,
    const wordList& coeffKeys
)
:
    name_(name),
    coeffDict_(coeffs)
{
    dictKeys::warnUnknown(coeffDict_, coeffKeys);
}


// * * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dpiFluidForce>
Foam::dpiFluidForce::New(const word& name, const dictionary& coeffs)
{
    Info<< "Selecting particle force " << name << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(coeffs)
            << "Unknown particle force " << name << " in " << coeffs.name()
            << nl << nl << "Valid particle forces :" << nl
            << dictionaryConstructorTablePtr_->sortedToc()
            << exit(FatalIOError);
    }

    return autoPtr<dpiFluidForce>(cstrIter()(name, coeffs));
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

void Foam::dpiFluidForce::sum
(
    const PtrList<dpiFluidForce>& forces,
    const fluidState& fl,
    const vector& v,
    const scalar d,
    const scalar N,
    vector& F,
    vector& Fc,
    scalar& Spc
)
{
    F = Zero;
    Fc = Zero;
    Spc = 0;
    if (fl.gasFree)
    {
        return;
    }

    forAll(forces, k)
    {
        const forceSuSp f = forces[k].parcelForce(fl, v, d, N);

        const vector Fk(f.Su + f.Sp*(fl.U + fl.Uturb - v));
        F += Fk;

        if (forces[k].coupled())
        {
            Fc += Fk;
            Spc += f.Sp;
        }
    }
}


void Foam::dpiFluidForce::linearise
(
    const PtrList<dpiFluidForce>& forces,
    const fluidState& fl,
    const vector& v,
    const scalar d,
    const scalar N,
    vector& Su,
    scalar& Sp,
    vector& SuC,
    scalar& SpC
)
{
    Su = Zero;
    Sp = 0;
    SuC = Zero;
    SpC = 0;
    if (fl.gasFree)
    {
        return;
    }

    forAll(forces, k)
    {
        const forceSuSp f = forces[k].parcelForce(fl, v, d, N);

        Su += f.Su;
        Sp += f.Sp;

        if (forces[k].coupled())
        {
            SuC += f.Su;
            SpC += f.Sp;
        }
    }
}


// ************************************************************************* //
