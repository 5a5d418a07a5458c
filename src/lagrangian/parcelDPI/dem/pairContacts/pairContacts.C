/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "pairContacts.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pairContacts::pairContacts(const scalar skin)
:
    search_(skin)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pairContacts::build
(
    const demState& s,
    const contactModels& models,
    const scalar range
)
{
    const label n = s.size();

    search_.build
    (
        s,
        [&models](const scalar ri, const scalar rj)
        {
            return models.maxPairRange(ri, rj);
        }
    );

    // The half list in globalId order
    const DynamicList<labelPair>& pairs = search_.pairs();
    const label np = pairs.size();
    const labelUList& id = s.globalId;

    labelList byId(identity(n));
    std::sort
    (
        byId.begin(),
        byId.end(),
        [&id](const label a, const label b) { return id[a] < id[b]; }
    );

    labelList fill(n, 0);
    for (const labelPair& pr : pairs)
    {
        ++fill[pr.first()];
    }

    pairRow_.setSize(n);
    pairStart_.setSize(n + 1);
    label nRows = 0;
    label k = 0;
    for (const label i : byId)
    {
        if (fill[i])
        {
            pairRow_[nRows] = i;
            pairStart_[nRows] = k;
            ++nRows;
            const label count = fill[i];
            fill[i] = k;
            k += count;
        }
    }
    pairStart_[nRows] = k;
    pairRow_.setSize(nRows);
    pairStart_.setSize(nRows + 1);

    pairJ_.setSize(np);
    for (const labelPair& pr : pairs)
    {
        pairJ_[fill[pr.first()]++] = pr.second();
    }

    for (label a = 0; a < nRows; ++a)
    {
        std::sort
        (
            pairJ_.begin() + pairStart_[a],
            pairJ_.begin() + pairStart_[a + 1],
            [&id](const label a, const label b) { return id[a] < id[b]; }
        );
    }

    // The cut-off of the global range (as before per-pair ranges) is kept
    // where it is the smaller, so that a pair at the edge of the range is
    // decided exactly as it was; the per-pair one has a margin far above
    // round-off, so it drops only pairs that are certainly out of range
    pairCut2_.setSize(np);
    forAll(pairRow_, a)
    {
        const label i = pairRow_[a];
        for (label k = pairStart_[a]; k < pairStart_[a + 1]; ++k)
        {
            const label j = pairJ_[k];
            const scalar rSum = s.r[i] + s.r[j];
            const scalar pairRange = models.maxPairRange(s.r[i], s.r[j]);
            pairCut2_[k] = min
            (
                sqr(rSum + range),
                sqr((rSum + pairRange)*(1 + 1e-9))
            );
        }
    }
}


// ************************************************************************* //
