/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "contactStatistics.H"
#include "Ostream.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactStatistics::contactStatistics(const wordList& types)
:
    types_(types),
    steps_(2*types.size()*types.size(), 0),
    started_(steps_.size(), 0),
    impulse_(steps_.size(), 0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactStatistics::reset()
{
    steps_ = 0;
    started_ = 0;
    impulse_ = 0;
}


void Foam::contactStatistics::writeHeader(Ostream& os) const
{
    os  << "# Touching contacts of each fluid step by class (pair of"
        << " material types, or type-wall:material), over the advancing"
        << " DEM sub-steps, each contact once" << nl
        << "# time class contactSteps started normalImpulse[N.s]" << nl;
}


void Foam::contactStatistics::write(const scalar t, Ostream& os) const
{
    labelField steps(steps_);
    labelField started(started_);
    scalarField impulse(impulse_);
    Foam::reduce(steps, sumOp<labelField>());
    Foam::reduce(started, sumOp<labelField>());
    Foam::reduce(impulse, sumOp<scalarField>());

    if (!Pstream::master())
    {
        return;
    }

    const label n = types_.size();
    forAll(steps, k)
    {
        if (!steps[k])
        {
            continue;
        }
        const label a = (k % (n*n))/n;
        const label b = k % n;
        const word name
        (
            k < n*n
          ? types_[a] + '-' + types_[b]
          : types_[a] + "-wall:" + types_[b]
        );
        os  << t << ' ' << name << ' ' << steps[k] << ' ' << started[k]
            << ' ' << impulse[k] << nl;
    }
    os.flush();
}


// ************************************************************************* //
