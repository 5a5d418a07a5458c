/*---------------------------------------------------------------------------*\
  dpiFoam: unit tests of the unknown-key warnings (dictKeys)
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.

Description
    A key no reader asks for is counted (and warned about), with the
    closest known key suggested when it is a likely typo and none when it
    is far from every known key; known keys, FoamFile and regular
    expression keys give nothing. The engine's own check: a <model>Coeffs
    of a model that is not selected is reported, the selected one's is not.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "dictKeys.H"
#include "demEngine.H"
#include "demMaterials.H"
#include "vdwGuParcel.H"
#include "typePairDicts.H"
#include "IStringStream.H"
#include <string>

using namespace Foam;

namespace
{

dictionary toDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

//- The engine's dictionary without walls, models as given
std::string demDeck(const std::string& models, const std::string& extra = "")
{
    return
        "timeStep 1e-8;"
        "types { api { diameter 5e-6; density 1520; youngsModulus 5e8;"
        "  poissonsRatio 0.35; } }"
        "pairs { default { restitution 0.85; friction 0.45; } }"
      + models + extra
      + "timeStepCheck { maxImpactVelocity 1; }";
}

const std::string defaultModels
(
    "normalModel hertzParcel; tangentialModel historyParcel;"
    "rollingModel none; cohesionModel none;"
);

} // End anonymous namespace


TEST(dictKeys, distanceCountsOneEditPerTypo)
{
    EXPECT_EQ(dictKeys::distance("restitution", "restitution"), 0);
    EXPECT_EQ(dictKeys::distance("restitutoin", "restitution"), 1);  // swap
    EXPECT_EQ(dictKeys::distance("frction", "friction"), 1);         // drop
    EXPECT_EQ(dictKeys::distance("Uu", "U"), 1);                     // extra
    EXPECT_EQ(dictKeys::distance("", "abc"), 3);
    EXPECT_EQ(dictKeys::distance("kitten", "sitting"), 3);
}


TEST(dictKeys, knownKeysGiveNoWarning)
{
    const dictionary d
    (
        toDict("restitution 0.85; friction 0.45; rollingFriction 0.05;")
    );
    EXPECT_EQ(dictKeys::warnUnknown(d, demMaterials::pairKeys), 0);

    // An empty dictionary and an empty known list
    EXPECT_EQ(dictKeys::warnUnknown(dictionary(), wordList()), 0);
}


TEST(dictKeys, unknownKeysAreCounted)
{
    const dictionary d
    (
        toDict("restitutoin 0.85; friction 0.45; temperature 300;")
    );
    EXPECT_EQ(dictKeys::warnUnknown(d, demMaterials::pairKeys), 2);

    // Nothing is known: every key counts
    EXPECT_EQ(dictKeys::warnUnknown(d, wordList()), 3);
}


TEST(dictKeys, skipsFoamFileAndRegexKeys)
{
    const dictionary d
    (
        toDict
        (
            "FoamFile { version 2.0; format ascii; }"
            "\"(restitution|friction)\" 0.5;"
            "friction 0.45;"
        )
    );
    EXPECT_EQ(dictKeys::warnUnknown(d, demMaterials::pairKeys), 0);
}


TEST(dictKeys, suggestsTheClosestKnownKey)
{
    EXPECT_EQ
    (
        dictKeys::suggest("restitutoin", demMaterials::pairKeys),
        word("restitution")
    );
    EXPECT_EQ
    (
        dictKeys::suggest("rollingFricton", demMaterials::pairKeys),
        word("rollingFriction")
    );
    EXPECT_EQ(dictKeys::suggest("Nn", demMaterials::typeKeys), word("N"));
    EXPECT_EQ
    (
        dictKeys::suggest("youngsmodulus", demMaterials::typeKeys),
        word("youngsModulus")
    );
    EXPECT_EQ
    (
        dictKeys::suggest
        (
            "hamakerConstnat",
            cohesionContactModels::vdwGuParcel::pairKeys
        ),
        word("hamakerConstant")
    );
    EXPECT_EQ
    (
        dictKeys::suggest
        (
            "Uu",
            wordList({"position", "U", "omega", "type", "d"})
        ),
        word("U")
    );
}


TEST(dictKeys, noSuggestionForAFarKey)
{
    const wordList& pairKeys = demMaterials::pairKeys;
    EXPECT_TRUE(dictKeys::suggest("temperature", pairKeys).empty());
    EXPECT_TRUE(dictKeys::suggest("hamakerConstant", pairKeys).empty());

    // Short keys allow one edit only: "xy" is not a typo of "U" or "d"
    EXPECT_TRUE
    (
        dictKeys::suggest("xy", wordList({"position", "U", "type", "d"}))
       .empty()
    );
    EXPECT_TRUE(dictKeys::suggest("anything", wordList()).empty());
}


// Both the pair entries and the default entry are checked
TEST(dictKeys, typePairEntries)
{
    const dictionary pairs
    (
        toDict
        (
            "default { restitution 0.85; friction 0.45; }"
            "a-b { restitutoin 0.5; }"
            "b-b { friction 0.3; hamakerConstant 1e-19; }"
        )
    );
    const typePairDicts pd(pairs, wordList({"a", "b"}));
    EXPECT_EQ(pd.warnUnknownKeys(demMaterials::pairKeys), 2);
}


// The dem dictionary: clean, an unknown key, the Coeffs of a model that is
// not selected (cdtCoeffs with rollingModel none), the selected one's
TEST(dictKeys, demEngineKeys)
{
    EXPECT_EQ(demEngine::warnUnknownKeys(toDict(demDeck(defaultModels))), 0);

    EXPECT_EQ
    (
        demEngine::warnUnknownKeys
        (
            toDict(demDeck(defaultModels, "neighbourSerach { skin 1e-5; }"))
        ),
        1
    );

    EXPECT_EQ
    (
        demEngine::warnUnknownKeys
        (
            toDict
            (
                demDeck
                (
                    defaultModels,
                    "cdtCoeffs { scaleTorqueWithN true; }"
                    "hertzParcelCoeffs { limitForce false; }"
                )
            )
        ),
        1
    );

    // A misspelt Coeffs of the selected model
    EXPECT_EQ
    (
        demEngine::warnUnknownKeys
        (
            toDict(demDeck(defaultModels, "hertzParcelCoefs { }"))
        ),
        1
    );
}


// The engine builds with an unknown key (a warning, not an error) and
// ignores it
TEST(dictKeys, unknownKeysDoNotStopTheEngine)
{
    FatalIOError.throwExceptions();

    const dictionary d
    (
        toDict
        (
            demDeck
            (
                defaultModels,
                "hertzParcelCoeffs { limitForce false; limitForse true; }"
                "startOverlap { warn 0.01; refuse 0.1; refuze 1; }"
            )
        )
    );
    EXPECT_NO_THROW(demEngine engine(d));
}


// ************************************************************************* //
