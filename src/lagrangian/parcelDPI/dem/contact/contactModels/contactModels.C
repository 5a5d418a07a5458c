/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "contactModels.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::contactModels::keys
({
    "normalModel",
    "tangentialModel",
    "rollingModel",
    "cohesionModel"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class Model>
bool modelExists(const Foam::word& model)
{
    return
        Model::dictionaryConstructorTablePtr_
     && Model::dictionaryConstructorTablePtr_->found(model);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::contactModels::exists(const word& key, const word& model)
{
    if (key == "normalModel")
    {
        return modelExists<normalContactModel>(model);
    }
    if (key == "tangentialModel")
    {
        return modelExists<tangentialContactModel>(model);
    }
    if (key == "rollingModel")
    {
        return modelExists<rollingContactModel>(model);
    }
    if (key == "cohesionModel")
    {
        return modelExists<cohesionContactModel>(model);
    }
    return false;
}


Foam::word Foam::contactModels::combination
(
    const word& normal,
    const word& tangential,
    const word& rolling,
    const word& cohesion
)
{
    return normal + '-' + tangential + '-' + rolling + '-' + cohesion;
}


Foam::label Foam::contactModels::warnUnusedCoeffs
(
    const dictionary& dict,
    wordList& known
)
{
    label nWarnings = 0;

    // The selected models' Coeffs are read by the models themselves
    for (const word& family : keys)
    {
        const word model(dict.getOrDefault<word>(family, word::null));
        if (model.size() && !known.found(model + "Coeffs"))
        {
            known.append(model + "Coeffs");
        }
    }

    // The Coeffs of a model that exists but is not selected is ignored
    // (usually a model switched off, e.g. rollingModel none with cdtCoeffs
    // left in place): say so, naming the model that is selected, rather
    // than calling it unknown
    const word suffix("Coeffs");
    for (const entry& e : dict)
    {
        const keyType& key = e.keyword();
        if
        (
            key.isPattern()
         || key.size() <= suffix.size()
         || !key.ends_with(suffix)
         || known.found(key)
        )
        {
            continue;
        }

        const word model(key.substr(0, key.size() - suffix.size()));
        for (const word& family : keys)
        {
            if (exists(family, model))
            {
                IOWarningInFunction(dict)
                    << "Dictionary '" << key.c_str() << "' in dictionary "
                    << dict.name().c_str() << " is not used: " << family
                    << " is "
                    << dict.getOrDefault<word>(family, word::null).c_str()
                    << " (" << key.c_str() << " is read only with "
                    << family << " " << model.c_str() << ")" << endl;

                known.append(key);
                ++nWarnings;
                break;
            }
        }
    }

    return nWarnings;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactModels::contactModels(const dictionary& dict)
:
    normal_(normalContactModel::New(dict)),
    tangential_(tangentialContactModel::New(dict)),
    rolling_(rollingContactModel::New(dict)),
    cohesion_(cohesionContactModel::New(dict))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::contactModels::combination() const
{
    return combination
    (
        normal_->type(),
        tangential_->type(),
        rolling_->type(),
        cohesion_->type()
    );
}


// ************************************************************************* //
