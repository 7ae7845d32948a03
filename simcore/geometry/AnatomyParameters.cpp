#include "simcore/geometry/AnatomyParameters.h"

namespace colonosim::geometry {

namespace {
using P = AnatomyParameters;
using F = params::Field<AnatomyParameters>;
constexpr std::array<F, 30> kFields{{
    {&P::rectumLengthSpec, &P::rectumLength},
    {&P::sigmoidLengthSpec, &P::sigmoidLength},
    {&P::descendingLengthSpec, &P::descendingLength},
    {&P::splenicFlexureLengthSpec, &P::splenicFlexureLength},
    {&P::transverseLengthSpec, &P::transverseLength},
    {&P::hepaticFlexureLengthSpec, &P::hepaticFlexureLength},
    {&P::ascendingLengthSpec, &P::ascendingLength},
    {&P::cecumLengthSpec, &P::cecumLength},
    {&P::rectumDiameterSpec, &P::rectumDiameter},
    {&P::sigmoidDiameterSpec, &P::sigmoidDiameter},
    {&P::descendingDiameterSpec, &P::descendingDiameter},
    {&P::splenicFlexureDiameterSpec, &P::splenicFlexureDiameter},
    {&P::transverseDiameterSpec, &P::transverseDiameter},
    {&P::hepaticFlexureDiameterSpec, &P::hepaticFlexureDiameter},
    {&P::ascendingDiameterSpec, &P::ascendingDiameter},
    {&P::cecumDiameterSpec, &P::cecumDiameter},
    {&P::ascendingMobileFractionSpec, &P::ascendingMobileFraction},
    {&P::descendingMobileSpec, &P::descendingMobile},
    {&P::transverseMesenteryHeightSpec, &P::transverseMesenteryHeight},
    {&P::sigmoidMesenteryHeightSpec, &P::sigmoidMesenteryHeight},
    {&P::mobileColonMesenteryHeightSpec, &P::mobileColonMesenteryHeight},
    {&P::sigmoidRootLengthSpec, &P::sigmoidRootLength},
    {&P::sigmoidSweepSpec, &P::sigmoidSweep},
    {&P::haustralFoldDepthSpec, &P::haustralFoldDepth},
    {&P::haustralFoldSpacingSpec, &P::haustralFoldSpacing},
    {&P::taeniaDepthSpec, &P::taeniaDepth},
    {&P::physicsNodesPerRingSpec, &P::physicsNodesPerRing},
    {&P::physicsTargetNodeCountSpec, &P::physicsTargetNodeCount},
    {&P::visualNodesPerRingSpec, &P::visualNodesPerRing},
    {&P::visualRingCountSpec, &P::visualRingCount},
}};
}  // namespace

std::span<const params::Field<AnatomyParameters>> AnatomyParameters::fields()
{
    return kFields;
}

void AnatomyParameters::validate() const
{
    params::validateFields<AnatomyParameters>("anatomy", fields(), *this);
}

double AnatomyParameters::length(Segment segment) const
{
    switch (segment) {
    case Segment::Rectum: return rectumLength;
    case Segment::Sigmoid: return sigmoidLength;
    case Segment::Descending: return descendingLength;
    case Segment::SplenicFlexure: return splenicFlexureLength;
    case Segment::Transverse: return transverseLength;
    case Segment::HepaticFlexure: return hepaticFlexureLength;
    case Segment::Ascending: return ascendingLength;
    case Segment::Cecum: return cecumLength;
    }
    return 0.0;
}

double AnatomyParameters::diameter(Segment segment) const
{
    switch (segment) {
    case Segment::Rectum: return rectumDiameter;
    case Segment::Sigmoid: return sigmoidDiameter;
    case Segment::Descending: return descendingDiameter;
    case Segment::SplenicFlexure: return splenicFlexureDiameter;
    case Segment::Transverse: return transverseDiameter;
    case Segment::HepaticFlexure: return hepaticFlexureDiameter;
    case Segment::Ascending: return ascendingDiameter;
    case Segment::Cecum: return cecumDiameter;
    }
    return 0.0;
}

double AnatomyParameters::totalLength() const
{
    double total = 0.0;
    for (int i = 0; i < kNumSegments; ++i) {
        total += length(static_cast<Segment>(i));
    }
    return total;
}

}  // namespace colonosim::geometry
