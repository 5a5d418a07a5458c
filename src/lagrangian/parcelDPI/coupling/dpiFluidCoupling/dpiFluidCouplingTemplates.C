/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpiFluidCoupling.H"
#include "interpolation.H"
#include "fvcGrad.H"
#include "Map.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::dpiFluidCoupling::sample(const CloudType& cloud, const demState& s)
{
    typedef typename CloudType::parcelType parcelType;

    gasMomentum_ = Zero;
    nRows_ = cloud.size();
    sampleTimeIndex_ = mesh_.time().timeIndex();

    if (s.size() < nRows_)
    {
        FatalErrorInFunction
            << "The DEM state has " << s.size() << " rows for "
            << nRows_ << " parcels" << exit(FatalError);
    }

    fluid_.setSize(nRows_);
    cell_.setSize(nRows_);
    fCoupled_.setSize(nRows_);
    spCoupled_.setSize(nRows_);
    spImpulse_.setSize(nRows_);
    spImpulse_ = 0;
    rowId_.setSize(nRows_);
    rowMass_.setSize(nRows_);
    spreadStart_.setSize(nRows_ + 1);
    spreadCells_.clear();
    spreadWeights_.clear();
    DynamicList<label> cells;
    DynamicList<scalar> weights;
    // Parallel: kernel points outside this sub-domain, found afterwards
    DynamicList<point> unresolved;
    DynamicList<point>* unresolvedPtr =
        Pstream::parRun() ? &unresolved : nullptr;
    DynamicList<point> remotePts;
    DynamicList<label> remoteRow;
    labelList aggId;
    if (dispersion_.valid())
    {
        sgs_.setSize(nRows_);
        aggId.setSize(nRows_);
    }

    autoPtr<interpolation<vector>> UInterp
    (
        interpolation<vector>::New(interpolation_, U_)
    );
    autoPtr<interpolation<scalar>> alphaInterp
    (
        interpolation<scalar>::New(interpolation_, *alpha_)
    );

    // Static pressure gradient [Pa/m]: the gas solves p/rho
    tmp<volVectorField> tgradp;
    autoPtr<interpolation<vector>> gradpInterp;
    bool kinematicP = false;
    if (p_)
    {
        tgradp = fvc::grad(*p_);
        gradpInterp = interpolation<vector>::New(interpolation_, tgradp());
        kinematicP = (p_->dimensions() == dimPressure/dimDensity);
    }

    // Resolved velocity gradient for the subgrid closures (cell values,
    // as the reference)
    tmp<volTensorField> tgradU;
    if (dispersion_.valid())
    {
        tgradU = fvc::grad(U_);
    }

    label i = 0;
    for (const parcelType& p : cloud)
    {
        if (s.globalId[i] != p.globalId())
        {
            FatalErrorInFunction
                << "Row " << i << " of the DEM state is parcel "
                << s.globalId[i] << ", expected " << p.globalId()
                << ": the rows must be the parcels in list order"
                << exit(FatalError);
        }

        const label celli = p.cell();
        const barycentric& coords = p.coordinates();
        const tetIndices tetIs(p.currentTetIndices());

        dpiFluidForce::fluidState& fl = fluid_[i];
        fl.U = UInterp->interpolate(coords, tetIs);
        fl.alpha = alphaInterp->interpolate(coords, tetIs);
        fl.rho = rho_[celli];
        fl.nu = mu_[celli]/rho_[celli];
        fl.Uturb = Zero;
        if (dispersion_.valid())
        {
            // u* of the parcel, kept in its UTurb between fluid steps
            fl.Uturb = p.UTurb();
            sgs_[i] = dispersion_->closure
            (
                tgradU()[celli],
                dispersion_->delta(mesh_.V()[celli]),
                fl.nu
            );
            aggId[i] = p.agglomerateId();
        }
        fl.gasFree = !gasFreeCell_.empty() && gasFreeCell_[celli];
        fl.gradp = Zero;
        if (gradpInterp.valid())
        {
            fl.gradp = gradpInterp->interpolate(coords, tetIs);
            if (kinematicP)
            {
                fl.gradp *= fl.rho;
            }
        }

        cell_[i] = celli;
        rowId_[i] = p.globalId();
        rowMass_[i] = s.N[i]*s.m[i];

        // Where the reaction goes: the void fraction's kernel, so that the
        // gas receives the force where it sees the parcel's volume
        spreadStart_[i] = spreadCells_.size();
        if (voidFraction_.valid())
        {
            dpiVoidFraction::pointWeights
            (
                mesh_, p.position(), celli, 0.5*p.d(), cells, weights,
                unresolvedPtr
            );
            spreadCells_.append(cells);
            spreadWeights_.append(weights);
            for (const point& pt : unresolved)
            {
                remotePts.append(pt);
                remoteRow.append(i);
            }
        }
        else
        {
            spreadCells_.append(celli);
            spreadWeights_.append(1);
        }
        ++i;
    }
    spreadStart_[nRows_] = spreadCells_.size();

    // The parcels of an agglomerate of the last step share one u*
    if (dispersion_.valid())
    {
        vectorField uStar(nRows_);
        for (label j = 0; j < nRows_; ++j)
        {
            uStar[j] = fluid_[j].Uturb;
        }
        dispersionKey_.setSize(nRows_);
        dispersion_->share
        (
            aggId, rowId_, rowMass_, uStar, sgs_, dispersionKey_
        );
        for (label j = 0; j < nRows_; ++j)
        {
            fluid_[j].Uturb = uStar[j];
        }
    }

    // Who holds the points outside this sub-domain (collective); those no
    // processor holds are outside the mesh: the row's own cell (which
    // pointWeights put among the row's cells), as in the serial kernel
    remote_ = dpiRemotePoints(mesh_, remotePts);
    remoteRow_.transfer(remoteRow);
    remoteUTrans_.setSize(remote_.size());
    remoteUTrans_ = Zero;
    remoteUCoeff_.setSize(remote_.size());
    remoteUCoeff_ = 0;
    const scalar wPt = 1.0/dpiVoidFraction::nPoints;
    forAll(remoteRow_, k)
    {
        if (!remote_.found(k))
        {
            const label row = remoteRow_[k];
            for (label j = spreadStart_[row]; j < spreadStart_[row+1]; ++j)
            {
                if (spreadCells_[j] == cell_[row])
                {
                    spreadWeights_[j] += wPt;
                    break;
                }
            }
        }
    }
}


template<class CloudType>
void Foam::dpiFluidCoupling::addSources
(
    CloudType& cloud,
    const UList<vector>& impulse,
    const UList<scalar>& spImp
)
{
    // The drag impulse on the parcels, for the log (coupled or not)
    for (label i = 0; i < nRows_; ++i)
    {
        gasMomentum_ -= impulse[i];
    }

    if (!cloud.solution().coupled())
    {
        return;
    }

    volVectorField::Internal& UTrans = cloud.UTrans();
    volScalarField::Internal& UCoeff = cloud.UCoeff();

    // As KinematicParcel: UTrans += -F dt (the gas's share of the
    // momentum), UCoeff += S_p dt; SU() divides by V and the fluid step.
    // Spread over the cells of the void fraction kernel with weights that
    // sum to one: the gas receives exactly -F dt in total
    for (label i = 0; i < nRows_; ++i)
    {
        const vector dU(-impulse[i]);
        const scalar dC(spImp[i]);
        for (label k = spreadStart_[i]; k < spreadStart_[i+1]; ++k)
        {
            UTrans[spreadCells_[k]] += spreadWeights_[k]*dU;
            UCoeff[spreadCells_[k]] += spreadWeights_[k]*dC;
        }
        spImpulse_[i] += dC;
    }

    // Points held by other processors: summed here, sent once per fluid
    // step (sendRemoteSources)
    const scalar wPt = 1.0/dpiVoidFraction::nPoints;
    forAll(remoteRow_, k)
    {
        if (remote_.found(k))
        {
            const label i = remoteRow_[k];
            remoteUTrans_[k] -= wPt*impulse[i];
            remoteUCoeff_[k] += wPt*spImp[i];
        }
    }
}


template<class CloudType>
void Foam::dpiFluidCoupling::sendRemoteSources(CloudType& cloud)
{
    if (!cloud.solution().coupled())
    {
        return;
    }

    remote_.add(remoteUTrans_, cloud.UTrans().field());
    remote_.add(remoteUCoeff_, cloud.UCoeff().field());
}


template<class CloudType>
void Foam::dpiFluidCoupling::correctParcels
(
    CloudType& cloud,
    const volVectorField& U
) const
{
    typedef typename CloudType::parcelType parcelType;

    if
    (
        !active()
     || sampleTimeIndex_ != mesh_.time().timeIndex()
     || !cloud.solution().coupled()
     || !cloud.solution().semiImplicit("U")
    )
    {
        return;
    }

    // The gas solved -S_p (U - U^o) besides the explicit -F: the parcels
    // get +S_p (U - U^o), i.e. they too see the new gas velocity in the
    // implicit part of their drag. The source coefficient scales UCoeff
    // (KinematicCloud::scaleSources), so it scales this counterpart too
    const scalar coeff = cloud.solution().relaxCoeff("U");
    const volVectorField& U0 = U.oldTime();

    // The gas velocity change at the points other processors hold (a
    // serial run has none: remoteRow_ is empty and nothing is built)
    vectorField dUremote;
    if (Pstream::parRun())
    {
        const vectorField dU(U.primitiveField() - U0.primitiveField());
        dUremote = remote_.fetch(dU);
    }
    const scalar wPt = 1.0/dpiVoidFraction::nPoints;

    List<vector> dUrow(nRows_, Zero);
    for (label i = 0; i < nRows_; ++i)
    {
        for (label k = spreadStart_[i]; k < spreadStart_[i+1]; ++k)
        {
            const label c = spreadCells_[k];
            dUrow[i] += spreadWeights_[k]*(U[c] - U0[c]);
        }
    }
    forAll(remoteRow_, k)
    {
        if (remote_.found(k))
        {
            dUrow[remoteRow_[k]] += wPt*dUremote[k];
        }
    }

    Map<vector> dv(2*nRows_);
    for (label i = 0; i < nRows_; ++i)
    {
        dv.insert(rowId_[i], coeff*spImpulse_[i]*dUrow[i]/rowMass_[i]);
    }

    // Parcels relocated on this processor
    for (parcelType& p : cloud)
    {
        const auto iter = dv.cfind(p.globalId());
        if (iter.found())
        {
            p.U() += *iter;
            dv.erase(p.globalId());
        }
    }

    if (Pstream::parRun())
    {
        // Parcels that moved to another processor in the relocation (those
        // that left through an open patch are gone on every processor)
        List<Map<vector>> remote(Pstream::nProcs());
        remote[Pstream::myProcNo()] = dv;
        Pstream::gatherList(remote);
        Pstream::scatterList(remote);

        for (parcelType& p : cloud)
        {
            forAll(remote, proci)
            {
                if (proci == Pstream::myProcNo())
                {
                    continue;
                }
                const auto iter = remote[proci].cfind(p.globalId());
                if (iter.found())
                {
                    p.U() += *iter;
                    break;
                }
            }
        }
    }
}


template<class CloudType>
void Foam::dpiFluidCoupling::startFluidStep
(
    const CloudType& cloud,
    demState& s,
    const scalar Dt,
    List<vectorField>& vecIn,
    List<scalarField>& scaIn
)
{
    if (!active())
    {
        return;
    }
    sample(cloud, s);
    if (subStepForces())
    {
        packStates(vecIn, scaIn);
    }
    else
    {
        setHeldForces(s, Dt);
    }
}


template<class CloudType>
void Foam::dpiFluidCoupling::finishFluidStep
(
    CloudType& cloud,
    const List<vectorField>& vecBack,
    const List<scalarField>& scaBack,
    const scalar Dt
)
{
    if (!active())
    {
        return;
    }
    if (subStepForces())
    {
        finishSubSteps(cloud, vecBack, scaBack);
    }
    else
    {
        finishHeld(cloud, Dt);
    }
}


template<class CloudType>
void Foam::dpiFluidCoupling::finishSubSteps
(
    CloudType& cloud,
    const List<vectorField>& vecOut,
    const List<scalarField>& scaOut
)
{
    for (label i = 0; i < nRows_; ++i)
    {
        fluid_[i].Uturb = vecOut[fluidColumns::uStar][i];
    }

    // The fluid step's impulse of each parcel, spread once
    addSources
    (
        cloud,
        vecOut[fluidColumns::impulse],
        scaOut[fluidColumns::spImpulse]
    );

    endFluidStep(cloud);
}


template<class CloudType>
void Foam::dpiFluidCoupling::finishHeld
(
    CloudType& cloud,
    const scalar Dt
)
{
    vectorField impulse(nRows_);
    scalarField spImp(nRows_);
    for (label i = 0; i < nRows_; ++i)
    {
        impulse[i] = Dt*fCoupled_[i];
        spImp[i] = Dt*spCoupled_[i];
    }
    addSources(cloud, impulse, spImp);
    endFluidStep(cloud);
}


template<class CloudType>
void Foam::dpiFluidCoupling::endFluidStep(CloudType& cloud)
{
    sendRemoteSources(cloud);

    if (dispersion_.valid())
    {
        // u* back into the parcels (rows in list order) and a log line
        typedef typename CloudType::parcelType parcelType;
        scalar sumU2 = 0;
        scalar kMax = 0;
        label i = 0;
        for (parcelType& p : cloud)
        {
            p.UTurb() = fluid_[i].Uturb;
            sumU2 += magSqr(fluid_[i].Uturb);
            kMax = max(kMax, sgs_[i].k);
            ++i;
        }
        reduce(sumU2, sumOp<scalar>());
        reduce(kMax, maxOp<scalar>());
        const label n = returnReduce(nRows_, sumOp<label>());
        Info<< "    Turbulent dispersion: rms u* "
            << Foam::sqrt(sumU2/max(3*n, 1)) << " m/s per component, max k "
            << kMax << " m2/s2" << endl;
    }

    Info<< "    Fluid coupling: momentum to the gas " << gasMomentum()
        << " kg m/s" << endl;
}


// ************************************************************************* //
