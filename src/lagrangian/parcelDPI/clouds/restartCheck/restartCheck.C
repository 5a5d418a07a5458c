/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "restartCheck.H"
#include "demMaterials.H"
#include "Pstream.H"
#include "PstreamCombineReduceOps.H"
#include "ops.H"
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    // A number as a user typed it (the streams carry the run's
    // writePrecision, often 15-17 digits: 5.0000000000000004e-06)
    std::string str(const scalar x)
    {
        std::ostringstream os;
        os << std::setprecision(6) << x;
        return os.str();
    }

    // Equal to the precision both the table and the fields are written with
    bool same(const scalar a, const scalar b)
    {
        return mag(a - b) <= 1e-6*max(mag(a), mag(b));
    }

    // Per written type index: parcels, smallest and largest diameter
    // (global)
    void typeStats
    (
        const label nTypes,
        const labelUList& typeId,
        const scalarUList& d,
        labelList& count,
        scalarList& dMin,
        scalarList& dMax
    )
    {
        count.setSize(nTypes, 0);
        dMin.setSize(nTypes, GREAT);
        dMax.setSize(nTypes, -GREAT);
        forAll(typeId, i)
        {
            const label t = typeId[i];
            if (t >= 0 && t < nTypes)
            {
                ++count[t];
                dMin[t] = min(dMin[t], d[i]);
                dMax[t] = max(dMax[t], d[i]);
            }
        }
        Pstream::listCombineGather(count, plusEqOp<label>());
        Pstream::listCombineScatter(count);
        Pstream::listCombineGather(dMin, minEqOp<scalar>());
        Pstream::listCombineScatter(dMin);
        Pstream::listCombineGather(dMax, maxEqOp<scalar>());
        Pstream::listCombineScatter(dMax);
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::restartCheck::writeTypes
(
    dictionary& dpiDict,
    const demMaterials& mat,
    const labelUList& typeId,
    const scalarUList& d
)
{
    labelList count;
    scalarList dMin, dMax;
    typeStats(mat.size(), typeId, d, count, dMin, dMax);

    dictionary types;
    forAll(mat.names(), t)
    {
        if (!mat.isParticleType(t))
        {
            continue;       // wall materials: no parcel carries them
        }
        dictionary row;
        row.add("N", mat.N(t));
        // One size, or the distribution the parcels were drawn from
        if (mat.size(t).fixed())
        {
            row.add("diameter", mat.size(t).minDiameter());
        }
        else
        {
            row.add("sizeDistribution", mat.size(t).description());
        }
        row.add("density", mat.density(t));
        row.add("parcels", count[t]);
        if (count[t])
        {
            row.add("dMin", dMin[t]);
            row.add("dMax", dMax[t]);
        }
        types.add(mat.names()[t], row);
    }
    dpiDict.set("typeNames", mat.names());
    dpiDict.set("types", types);
}


Foam::labelList Foam::restartCheck::mapTypes
(
    const dictionary& dpiDict,
    const dictionary& demDict,
    const demMaterials& mat,
    const word& timeName,
    const labelUList& typeId,
    const labelUList& globalId,
    const scalarUList& d,
    const scalarUList& N,
    const scalarUList& rho
)
{
    if (!dpiDict.found("typeNames"))
    {
        WarningInFunction
            << "The cloud state of time " << timeName << " has no type table"
            << " (written by an older dpiFoam): the parcels' typeIds are"
            << " taken in the order of " << demDict.name() << "/types,"
            << " unchecked" << endl;
        return labelList();
    }

    const wordList written(dpiDict.get<wordList>("typeNames"));
    const dictionary& table = dpiDict.subDict("types");
    const label nWritten = written.size();

    // A typeId outside the written table
    string reason;
    forAll(typeId, i)
    {
        if (typeId[i] < 0 || typeId[i] >= nWritten)
        {
            reason =
                "Parcel " + Foam::name(globalId[i]) + " at time " + timeName
              + " has typeId " + Foam::name(typeId[i]) + ", but the types"
              + " written with that time are numbered 0 to "
              + Foam::name(nWritten - 1) + ": the typeId field was edited"
              + " or belongs to another case.";
            break;
        }
    }
    refuseIfAny(reason, demDict);

    labelList count;
    scalarList dMin, dMax;
    typeStats(nWritten, typeId, d, count, dMin, dMax);

    labelList newIndex(nWritten, -1);
    forAll(written, t)
    {
        newIndex[t] = mat.names().find(written[t]);

        const dictionary* rowPtr = table.findDict(written[t]);
        if (!count[t])
        {
            continue;       // no parcel of this type: nothing to keep
        }
        if (newIndex[t] < 0 || !rowPtr)
        {
            FatalIOErrorInFunction(demDict)
                << "The parcels at time " << timeName << " include "
                << count[t] << " of type " << written[t] << ", which is not"
                << " in " << demDict.name() << "/types " << mat.names()
                << nl << "    A restart matches the parcels' types by name:"
                << " keep type " << written[t] << " in dem/types."
                << exit(FatalIOError);
        }

        // What the parcels were made with cannot change in a restart: each
        // parcel carries its N, diameter and density from its injection
        const dictionary& row = *rowPtr;
        const label n = newIndex[t];
        const scalar Nw = row.get<scalar>("N");
        const scalar rhow = row.get<scalar>("density");
        const sizeDistribution& size = mat.size(n);
        const bool fixedBoth = row.found("diameter") && size.fixed();
        const scalar dw =
            fixedBoth ? row.get<scalar>("diameter") : size.minDiameter();
        const Pair<scalar> changes[3] =
        {
            {Nw, mat.N(n)}, {rhow, mat.density(n)}, {dw, size.minDiameter()}
        };
        const char* keys[3] = {"N", "density", "diameter"};

        // A size distribution, or a change between one size and a
        // distribution, is compared as its description
        const std::string sizeWritten =
            row.found("diameter")
          ? "diameter " + str(row.get<scalar>("diameter"))
          : "sizeDistribution '"
          + std::string(row.get<string>("sizeDistribution")) + "'";
        const std::string sizeNow =
            size.fixed()
          ? "diameter " + str(size.minDiameter())
          : "sizeDistribution '" + std::string(size.description()) + "'";
        if (!fixedBoth && sizeWritten != sizeNow)
        {
            FatalIOErrorInFunction(demDict)
                << "Type " << written[t] << " has " << sizeNow.c_str()
                << " in " << demDict.name() << "/types/" << written[t]
                << ", but its " << count[t] << " parcels at time "
                << timeName << " were injected with " << sizeWritten.c_str()
                << "." << nl
                << "    A restart cannot change what the parcels were made"
                << " with: restore the type's size as written, or change it"
                << " from the injection on (startTime 0)"
                << exit(FatalIOError);
        }

        for (label k = 0; k < 3; ++k)
        {
            if (!same(changes[k].first(), changes[k].second()))
            {
                FatalIOErrorInFunction(demDict)
                    << "Type " << written[t] << " has " << keys[k] << " "
                    << str(changes[k].second()).c_str() << " in "
                    << demDict.name()
                    << "/types/" << written[t] << ", but its " << count[t]
                    << " parcels at time " << timeName << " were injected"
                    << " with " << keys[k] << " "
                    << str(changes[k].first()).c_str() << "." << nl
                    << "    A restart cannot change what the parcels were"
                    << " made with (each carries its N, diameter and"
                    << " density): set " << keys[k] << " "
                    << str(changes[k].first()).c_str() << ", or change it from the"
                    << " injection on (startTime 0). Material and model"
                    << " coefficients (youngsModulus, restitution,"
                    << " hamakerConstant, ...) may change."
                    << exit(FatalIOError);
            }
        }

        // The fields against the table written with them: an edited
        // typeId or field, or files mixed from two times
        const label nw = row.get<label>("parcels");
        if (count[t] != nw)
        {
            FatalIOErrorInFunction(demDict)
                << "Time " << timeName << " has " << count[t] << " parcels"
                << " of type " << written[t] << " (typeId " << t << "), but"
                << " the cloud state written with it counts " << nw << ":"
                << " the typeId field was edited after writing, or the"
                << " cloud's files come from different times."
                << exit(FatalIOError);
        }
        const scalar lo = row.get<scalar>("dMin");
        const scalar hi = row.get<scalar>("dMax");
        forAll(typeId, i)
        {
            if (typeId[i] != t || reason.size())
            {
                continue;
            }
            if
            (
                !same(N[i], Nw) || !same(rho[i], rhow)
             || (d[i] < lo && !same(d[i], lo))
             || (d[i] > hi && !same(d[i], hi))
            )
            {
                reason =
                    "Parcel " + Foam::name(globalId[i]) + " at time "
                  + timeName + " has typeId " + Foam::name(t) + " (type "
                  + written[t] + ": N " + str(Nw) + ", density "
                  + str(rhow) + ", d from " + str(lo) + " to "
                  + str(hi) + ") but N " + str(N[i])
                  + ", density " + str(rho[i]) + ", d "
                  + str(d[i]) + ": the typeId field or that"
                  + " parcel's fields were edited after writing.";
            }
        }
    }
    refuseIfAny(reason, demDict);

    // Say when the order changed (nothing else is needed: the typeIds are
    // remapped)
    bool reordered = false;
    forAll(newIndex, t)
    {
        reordered = reordered || (count[t] && newIndex[t] != t);
    }
    if (reordered)
    {
        Info<< "    dem/types is in another order than when time "
            << timeName << " was written (then " << written << ", now "
            << mat.names() << "): the parcels' types are matched by name"
            << endl;
    }
    return newIndex;
}


void Foam::restartCheck::refuseIfAny
(
    const string& reason,
    const dictionary& context
)
{
    List<string> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = reason;
    Pstream::gatherList(all);

    string first;
    if (Pstream::master())
    {
        for (const string& r : all)
        {
            if (r.size())
            {
                first = r;
                break;
            }
        }
    }
    Pstream::scatter(first);
    if (first.empty())
    {
        return;
    }
    if (!Pstream::master())
    {
        Pstream::exit(1);
    }
    FatalIOErrorInFunction(context)
        << first.c_str() << exit(FatalIOError);
}


Foam::labelHashSet Foam::restartCheck::globalIds
(
    const labelUList& local,
    const word& timeName
)
{
    List<labelList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    Pstream::scatterList(all);

    labelHashSet ids;
    string reason;
    forAll(all, proci)
    {
        for (const label id : all[proci])
        {
            if (!ids.insert(id) && reason.empty())
            {
                reason =
                    "Two parcels at time " + timeName + " carry globalId "
                  + Foam::name(id) + ": the cloud's ids must be unique"
                  + " (contact histories and agglomerates are keyed by"
                  + " them). The globalId field was edited or the cloud's"
                  + " files were merged from two runs.";
            }
        }
    }
    // Every processor saw the same lists: all stop together
    if (reason.size())
    {
        if (!Pstream::master())
        {
            Pstream::exit(1);
        }
        FatalErrorInFunction << reason.c_str() << exit(FatalError);
    }
    return ids;
}


void Foam::restartCheck::checkHistory
(
    const label id,
    labelField& keys,
    vectorField& xi,
    const labelHashSet& all,
    const label nIssued,
    const label nWalls,
    const word& timeName,
    string& reason,
    label& nDropped
)
{
    label n = 0;
    forAll(keys, k)
    {
        const label key = keys[k];
        const bool isWall = key < 0;
        const label wall = isWall ? (-1 - key) % 128 : -1;
        if
        (
            reason.empty()
         && ((!isWall && key >= nIssued) || (isWall && wall >= nWalls))
        )
        {
            reason =
                "Parcel " + Foam::name(id) + " at time "
              + timeName + " has a contact history with "
              + (
                    isWall
                  ? "wall " + Foam::name(wall) + ", but dem/walls has "
                    + Foam::name(nWalls)
                  : "parcel " + Foam::name(key) + ", but only "
                    + Foam::name(nIssued) + " ids were issued"
                )
              + ": the contactKeys field was edited or belongs to"
              + " another case.";
        }
        if (!isWall && !all.found(key))
        {
            ++nDropped;
            continue;
        }
        keys[n] = key;
        xi[n] = xi[k];
        ++n;
    }
    keys.setSize(n);
    xi.setSize(n);
}


// ************************************************************************* //
