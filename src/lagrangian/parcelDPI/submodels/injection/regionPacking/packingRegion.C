/*---------------------------------------------------------------------------*\
  dpiFoam: CFD-DEM for dry powder inhalers
-------------------------------------------------------------------------------
License
    This file is part of dpiFoam, distributed under the GNU General Public
    License version 3 or (at your option) any later version; see LICENSE.
\*---------------------------------------------------------------------------*/

#include "packingRegion.H"
#include "dictKeys.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::packingRegion::readLength
(
    const dictionary& dict,
    const word& key,
    const bool allowZero
)
{
    const scalar x = dict.get<scalar>(key);
    if (allowZero ? !(x >= 0) : !(x > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << x << " in dictionary "
            << dict.name() << " must be " << (allowZero ? ">= 0" : "> 0")
            << exit(FatalIOError);
    }
    return x;
}


void Foam::packingRegion::setAxis(const dictionary& dict)
{
    const vector d(p2_ - p1_);
    length_ = mag(d);
    if (!(length_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'point1' and 'point2' of dictionary " << dict.name()
            << " coincide: the " << shapeName_ << " has no axis"
            << exit(FatalIOError);
    }
    axis_ = d/length_;

    // The Cartesian direction least aligned with the axis
    vector ref(1, 0, 0);
    if (mag(axis_.y()) < mag(axis_.x()) && mag(axis_.y()) <= mag(axis_.z()))
    {
        ref = vector(0, 1, 0);
    }
    else if (mag(axis_.z()) < mag(axis_.x()))
    {
        ref = vector(0, 0, 1);
    }
    e1_ = axis_ ^ ref;
    e1_ /= mag(e1_);
    e2_ = axis_ ^ e1_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::packingRegion::packingRegion(const dictionary& dict)
:
    shape_(shapeType::sphere),
    shapeName_(dict.get<word>("shape")),
    p1_(Zero),
    p2_(Zero),
    radius1_(0),
    radius2_(0),
    axis_(0, 0, 1),
    length_(0),
    e1_(1, 0, 0),
    e2_(0, 1, 0)
{
    // The keys each shape reads below; checked first so that a misspelt
    // one is named before the error for the missing entry
    wordList known({"shape"});
    if (shapeName_ == "sphere")
    {
        known.append(wordList({"centre", "radius"}));
    }
    else if (shapeName_ == "box")
    {
        known.append(wordList({"min", "max"}));
    }
    else if (shapeName_ == "cylinder")
    {
        known.append(wordList({"point1", "point2", "radius"}));
    }
    else if (shapeName_ == "cone")
    {
        known.append(wordList({"point1", "point2", "radius1", "radius2"}));
    }
    if (known.size() > 1)
    {
        dictKeys::warnUnknown(dict, known);
    }

    if (shapeName_ == "sphere")
    {
        shape_ = shapeType::sphere;
        p1_ = dict.get<point>("centre");
        radius1_ = readLength(dict, "radius");
        radius2_ = radius1_;
    }
    else if (shapeName_ == "box")
    {
        shape_ = shapeType::box;
        p1_ = dict.get<point>("min");
        p2_ = dict.get<point>("max");
        for (direction c = 0; c < 3; ++c)
        {
            if (!(p2_[c] > p1_[c]))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'max' " << p2_ << " of dictionary "
                    << dict.name() << " must exceed 'min' " << p1_
                    << " in every component" << exit(FatalIOError);
            }
        }
    }
    else if (shapeName_ == "cylinder")
    {
        shape_ = shapeType::cylinder;
        p1_ = dict.get<point>("point1");
        p2_ = dict.get<point>("point2");
        radius1_ = readLength(dict, "radius");
        radius2_ = radius1_;
        setAxis(dict);
    }
    else if (shapeName_ == "cone")
    {
        shape_ = shapeType::cone;
        p1_ = dict.get<point>("point1");
        p2_ = dict.get<point>("point2");
        radius1_ = readLength(dict, "radius1", true);
        radius2_ = readLength(dict, "radius2", true);
        if (!(max(radius1_, radius2_) > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entries 'radius1' and 'radius2' of dictionary "
                << dict.name() << " are both zero" << exit(FatalIOError);
        }
        setAxis(dict);
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown shape '" << shapeName_ << "' for entry 'shape' in "
            << "dictionary " << dict.name() << nl
            << "Valid shapes: (sphere box cylinder cone)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::packingRegion::volume() const
{
    using constant::mathematical::pi;

    switch (shape_)
    {
        case shapeType::sphere:
            return 4.0/3.0*pi*pow3(radius1_);
        case shapeType::box:
            return cmptProduct(p2_ - p1_);
        case shapeType::cylinder:
            return pi*sqr(radius1_)*length_;
        case shapeType::cone:
            return
                pi*length_/3
               *(sqr(radius1_) + radius1_*radius2_ + sqr(radius2_));
    }
    return 0;
}


Foam::boundBox Foam::packingRegion::bounds() const
{
    switch (shape_)
    {
        case shapeType::sphere:
            return boundBox
            (
                p1_ - vector::uniform(radius1_),
                p1_ + vector::uniform(radius1_)
            );
        case shapeType::box:
            return boundBox(p1_, p2_);
        case shapeType::cylinder:
        case shapeType::cone:
        {
            // The hull of the two end discs: a disc of radius r with unit
            // normal a reaches r sqrt(1 - a_i^2) along axis i (a box of
            // the radius every way would stick out along the axis, and an
            // injector whose region fits the mesh would be refused)
            const vector a((p2_ - p1_)/mag(p2_ - p1_));
            vector reach;
            for (direction i = 0; i < vector::nComponents; ++i)
            {
                reach[i] = Foam::sqrt(max(scalar(0), 1 - sqr(a[i])));
            }
            boundBox bb(p1_ - radius1_*reach, p1_ + radius1_*reach);
            bb.add(p2_ - radius2_*reach);
            bb.add(p2_ + radius2_*reach);
            return bb;
        }
    }
    return boundBox();
}


bool Foam::packingRegion::contains(const point& p, const scalar r) const
{
    switch (shape_)
    {
        case shapeType::sphere:
            return magSqr(p - p1_) <= sqr(radius1_ - r) && r <= radius1_;

        case shapeType::box:
            for (direction c = 0; c < 3; ++c)
            {
                if (p[c] < p1_[c] + r || p[c] > p2_[c] - r)
                {
                    return false;
                }
            }
            return true;

        case shapeType::cylinder:
        case shapeType::cone:
        {
            const vector d(p - p1_);
            const scalar t = d & axis_;
            if (t < r || t > length_ - r)
            {
                return false;
            }
            const scalar rho = mag(d - t*axis_);

            // Signed distance to the generator line through (0, R1) and
            // (L, R2) in the meridian plane, positive outside
            const scalar dR = radius2_ - radius1_;
            const scalar norm = sqrt(sqr(length_) + sqr(dR));
            const scalar dist = (-dR*t + length_*(rho - radius1_))/norm;
            return dist <= -r;
        }
    }
    return false;
}


bool Foam::packingRegion::fits(const scalar r) const
{
    switch (shape_)
    {
        case shapeType::sphere:
            return r <= radius1_;
        case shapeType::box:
            return cmptMin(p2_ - p1_) >= 2*r;
        case shapeType::cylinder:
            return length_ >= 2*r && radius1_ >= r;
        case shapeType::cone:
        {
            // Centres on the axis at t = r or t = L - r are the best
            // candidates near the wider end; check a few along the axis
            if (length_ < 2*r)
            {
                return false;
            }
            for (label k = 0; k <= 100; ++k)
            {
                const scalar t = r + (length_ - 2*r)*k/100.0;
                if (contains(p1_ + t*axis_, r))
                {
                    return true;
                }
            }
            return false;
        }
    }
    return false;
}


bool Foam::packingRegion::sample
(
    Random& rnd,
    const scalar r,
    point& p,
    const label maxTries
) const
{
    for (label k = 0; k < maxTries; ++k)
    {
        point q;
        switch (shape_)
        {
            case shapeType::sphere:
            {
                const scalar a = radius1_ - r;
                q = p1_
                  + a*vector
                    (
                        2*rnd.sample01<scalar>() - 1,
                        2*rnd.sample01<scalar>() - 1,
                        2*rnd.sample01<scalar>() - 1
                    );
                break;
            }
            case shapeType::box:
            {
                const vector lo(p1_ + vector::uniform(r));
                const vector span(p2_ - p1_ - vector::uniform(2*r));
                q = lo
                  + vector
                    (
                        span.x()*rnd.sample01<scalar>(),
                        span.y()*rnd.sample01<scalar>(),
                        span.z()*rnd.sample01<scalar>()
                    );
                break;
            }
            case shapeType::cylinder:
            case shapeType::cone:
            {
                const scalar a = max(radius1_, radius2_) - r;
                const scalar t = r + (length_ - 2*r)*rnd.sample01<scalar>();
                const scalar u = a*(2*rnd.sample01<scalar>() - 1);
                const scalar w = a*(2*rnd.sample01<scalar>() - 1);
                q = p1_ + t*axis_ + u*e1_ + w*e2_;
                break;
            }
        }

        if (contains(q, r))
        {
            p = q;
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
