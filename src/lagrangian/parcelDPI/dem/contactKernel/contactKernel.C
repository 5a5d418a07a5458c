/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "contactKernelOf.H"
#include "hertzParcel.H"
#include "historyParcel.H"
#include "cdt.H"
#include "noRolling.H"
#include "vdwGuParcel.H"
#include "noCohesion.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- One compiled combination: its name and its constructor
struct compiledLaw
{
    word (*name)();
    contactKernel* (*create)(const contactModels&);
};

template<class N, class T, class R, class C>
word lawName()
{
    return contactModels::combination
    (
        N::typeName, T::typeName, R::typeName, C::typeName
    );
}

template<class N, class T, class R, class C>
contactKernel* createLaw(const contactModels& models)
{
    return new contactKernelOf<contactLaw<N, T, R, C>>(models);
}

using hertz = normalContactModels::hertzParcel;
using history = tangentialContactModels::historyParcel;
using cdt = rollingContactModels::cdt;
using noRolling = rollingContactModels::noRolling;
using vdwGu = cohesionContactModels::vdwGuParcel;
using noCohesion = cohesionContactModels::noCohesion;

#define compiledContactLaw(N, T, R, C)                                        \
    { &lawName<N, T, R, C>, &createLaw<N, T, R, C> }

//- The combinations compiled. A new model needs its combinations here: one
//  line each, the four classes in chain order
const compiledLaw compiledLaws[] =
{
    compiledContactLaw(hertz, history, noRolling, noCohesion),
    compiledContactLaw(hertz, history, cdt, noCohesion),
    compiledContactLaw(hertz, history, noRolling, vdwGu),
    compiledContactLaw(hertz, history, cdt, vdwGu)
};

#undef compiledContactLaw

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::wordList Foam::contactKernel::compiled()
{
    wordList names;
    for (const compiledLaw& law : compiledLaws)
    {
        names.append(law.name());
    }
    return names;
}


Foam::autoPtr<Foam::contactKernel> Foam::contactKernel::New
(
    const contactModels& models,
    const dictionary& dict
)
{
    const word combination(models.combination());

    for (const compiledLaw& law : compiledLaws)
    {
        if (law.name() == combination)
        {
            return autoPtr<contactKernel>(law.create(models));
        }
    }

    FatalIOErrorInFunction(dict)
        << "The contact models " << contactModels::keys << " = "
        << combination << " in dictionary " << dict.name()
        << " are not a compiled combination." << nl
        << "    Compiled (normal-tangential-rolling-cohesion): "
        << compiled() << nl
        << "    The contact law is composed at compile time (no virtual call"
        << " per contact): add the combination to the list in"
        << " src/lagrangian/parcelDPI/dem/contactKernel/contactKernel.C and"
        << " rebuild" << exit(FatalIOError);

    return nullptr;
}


// ************************************************************************* //
