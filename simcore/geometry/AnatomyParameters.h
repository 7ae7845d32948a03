#pragma once
/// \file
/// Declared parameters of one procedural colon: segment lengths and distended
/// lumen diameters, mobility, mesentery heights, haustral folds and mesh
/// resolution. Every value is SI and declared once (see params/Parameter.h).
///
/// Sources (../shared/reference/population-statistics.md, section 6 and the
/// Hanson row of section 4):
/// - total length 150.3 ± 18.5 cm, range 110–196 cm (Utano et al. 2021) and
///   189.5 ± 26.3 cm (Khashab et al. 2009); transverse median 40–48 cm
///   (Saunders et al. 1996); redundant colons: sigmoid 66.8 cm, transverse
///   66.3 cm, total 210.8 cm (Hanson et al. 2007).
/// - distended lumen diameter: ascending median 46 mm (26–63), descending
///   29 mm (16–48), transverse < 6 cm, cecum < 9 cm (radiology references).
/// - mesentery height: transverse 7.4 ± 3.6 cm, sigmoid 6.3 ± 2.6 cm (cadaver
///   study, Ann R Coll Surg Engl 2015); part of the ascending colon mobile in
///   about 2/3 of people, descending mobile in about 1/3 (same study).
/// - mesh resolution: the CSIRO simulator used 1,872 physics nodes and about
///   54,000 visual vertices (de Visser et al. 2010).

#include "simcore/geometry/Segment.h"
#include "simcore/params/Parameter.h"

#include <array>
#include <span>

namespace colonosim::geometry {

struct AnatomyParameters {
    using Spec = params::ParameterSpec;
    static constexpr const char* kSixSrc = "population-statistics.md §6 (Utano 2021, Khashab 2009, Saunders "
                                           "1996); Hanson 2007 for redundant colons";
    static constexpr const char* kDiaSrc =
        "population-statistics.md §6, lumen diameter (radiology references)";

    // Segment lengths along the centreline, anus to cecum.
    static constexpr Spec rectumLengthSpec{
        "rectumLength", "m", 0.15, 0.10, 0.20, "rectum length, anal verge to rectosigmoid junction", kSixSrc};
    static constexpr Spec sigmoidLengthSpec{
        "sigmoidLength", "m", 0.40, 0.20, 0.70, "sigmoid length (66.8 cm in incomplete examinations)",
        kSixSrc};
    static constexpr Spec descendingLengthSpec{"descendingLength",        "m",    0.25, 0.15, 0.35,
                                               "descending colon length", kSixSrc};
    static constexpr Spec splenicFlexureLengthSpec{"splenicFlexureLength",   "m",    0.08, 0.04, 0.12,
                                                   "splenic flexure length", kSixSrc};
    static constexpr Spec transverseLengthSpec{"transverseLength",
                                               "m",
                                               0.48,
                                               0.30,
                                               0.70,
                                               "transverse colon length (median 40–48 cm, 66.3 cm redundant)",
                                               kSixSrc};
    static constexpr Spec hepaticFlexureLengthSpec{"hepaticFlexureLength",   "m",    0.07, 0.04, 0.12,
                                                   "hepatic flexure length", kSixSrc};
    static constexpr Spec ascendingLengthSpec{"ascendingLength",        "m",    0.17, 0.10, 0.25,
                                              "ascending colon length", kSixSrc};
    static constexpr Spec cecumLengthSpec{
        "cecumLength", "m", 0.06, 0.04, 0.09, "cecum length, ileocecal valve to cecal base", kSixSrc};

    // Distended lumen diameters.
    static constexpr Spec rectumDiameterSpec{
        "rectumDiameter", "m", 0.040, 0.025, 0.060, "distended rectal lumen diameter", kDiaSrc};
    static constexpr Spec sigmoidDiameterSpec{
        "sigmoidDiameter", "m", 0.030, 0.016, 0.050, "distended sigmoid lumen diameter", kDiaSrc};
    static constexpr Spec descendingDiameterSpec{"descendingDiameter",
                                                 "m",
                                                 0.029,
                                                 0.016,
                                                 0.048,
                                                 "distended descending lumen diameter, median 29 mm (16–48)",
                                                 kDiaSrc};
    static constexpr Spec splenicFlexureDiameterSpec{"splenicFlexureDiameter",
                                                     "m",
                                                     0.035,
                                                     0.020,
                                                     0.055,
                                                     "distended splenic flexure lumen diameter",
                                                     kDiaSrc};
    static constexpr Spec transverseDiameterSpec{"transverseDiameter",
                                                 "m",
                                                 0.045,
                                                 0.025,
                                                 0.060,
                                                 "distended transverse lumen diameter (< 6 cm)",
                                                 kDiaSrc};
    static constexpr Spec hepaticFlexureDiameterSpec{"hepaticFlexureDiameter",
                                                     "m",
                                                     0.045,
                                                     0.025,
                                                     0.060,
                                                     "distended hepatic flexure lumen diameter",
                                                     kDiaSrc};
    static constexpr Spec ascendingDiameterSpec{"ascendingDiameter",
                                                "m",
                                                0.046,
                                                0.026,
                                                0.063,
                                                "distended ascending lumen diameter, median 46 mm (26–63)",
                                                kDiaSrc};
    static constexpr Spec cecumDiameterSpec{
        "cecumDiameter", "m", 0.060, 0.035, 0.090, "distended cecal lumen diameter (< 9 cm)", kDiaSrc};

    // Mobility and mesenteries.
    static constexpr Spec ascendingMobileFractionSpec{
        "ascendingMobileFraction",
        "1",
        0.5,
        0.0,
        1.0,
        "fraction of ascending colon + cecum (from the cecal end) that hangs on a mesentery; some part is "
        "mobile in ~2/3 of people",
        "population-statistics.md §6, mobility (cadaver study, Ann R Coll Surg Engl 2015)"};
    static constexpr Spec descendingMobileSpec{
        "descendingMobile",
        "1",
        0.0,
        0.0,
        1.0,
        "1 when the descending colon hangs on a mesentery (~1/3 of people), 0 when retroperitoneal; values "
        ">= 0.5 count as mobile",
        "population-statistics.md §6, mobility (cadaver study, Ann R Coll Surg Engl 2015)"};
    static constexpr Spec transverseMesenteryHeightSpec{
        "transverseMesenteryHeight",
        "m",
        0.074,
        0.010,
        0.200,
        "transverse mesocolon height, 7.4 ± 3.6 cm",
        "population-statistics.md §6 (cadaver study, Ann R Coll Surg Engl 2015)"};
    static constexpr Spec sigmoidMesenteryHeightSpec{
        "sigmoidMesenteryHeight",
        "m",
        0.063,
        0.010,
        0.150,
        "sigmoid mesocolon height, 6.3 ± 2.6 cm",
        "population-statistics.md §6 (cadaver study, Ann R Coll Surg Engl 2015)"};
    static constexpr Spec mobileColonMesenteryHeightSpec{
        "mobileColonMesenteryHeight",
        "m",
        0.030,
        0.005,
        0.100,
        "mesentery height of a mobile ascending colon, cecum or descending colon",
        "assumption: no measured value; shorter than the transverse and sigmoid mesocolon"};
    static constexpr Spec sigmoidRootLengthSpec{
        "sigmoidRootLength",
        "m",
        0.0,
        0.0,
        0.30,
        "length of one root line on the posterior wall that the whole sigmoid hangs from, centred on the "
        "chord between the sigmoid's two ends, each ring tethered to its nearest point on it; 0: each ring "
        "hangs from a point sigmoidMesenteryHeight behind it",
        "assumption: no measured root length; a long sigmoid on a narrow mesocolon root swings round it "
        "(the anatomy of alpha looping and sigmoid volvulus; a short or fixed sigmoid mesocolon allows no "
        "alpha or spiral loop, Cotton and Williams); 0.17 m, the chord of the 66 cm redundant sigmoid, "
        "forms a crossed loop under a push (tests/procedure/SigmoidLoopTest.cpp)"};
    static constexpr Spec sigmoidSweepSpec{
        "sigmoidSweep",
        "1",
        1.0,
        -1.0,
        1.0,
        "sideways swing of the sigmoid loop, seen from the front: +1 swings first to the patient's right, "
        "over the top and down to the left (clockwise on an anterior view); -1 the mirror image, first "
        "to the left (counter-clockwise); values between narrow the swing",
        "assumption: the sigmoid's position and configuration vary widely between people (population-"
        "statistics.md §6, mobility); which way a redundant loop turns sets the handedness of a loop "
        "pushed into it (tests/procedure/SigmoidLoopTest.cpp)"};

    // Haustral folds and taeniae (visual mesh only).
    static constexpr Spec haustralFoldDepthSpec{
        "haustralFoldDepth",
        "m",
        0.004,
        0.0,
        0.012,
        "how far a haustral fold projects into the lumen",
        "assumption, typical endoscopic appearance (no reference table)"};
    static constexpr Spec haustralFoldSpacingSpec{
        "haustralFoldSpacing",
        "m",
        0.030,
        0.010,
        0.080,
        "distance between neighbouring haustral folds",
        "assumption, typical endoscopic appearance (no reference table)"};
    static constexpr Spec taeniaDepthSpec{
        "taeniaDepth",
        "m",
        0.0015,
        0.0,
        0.005,
        "inward flattening of the wall along each of the three taeniae coli",
        "assumption (no reference table)"};

    // Mesh resolution.
    static constexpr Spec physicsNodesPerRingSpec{"physicsNodesPerRing",
                                                  "1",
                                                  16,
                                                  6,
                                                  64,
                                                  "physics nodes around each ring",
                                                  "de Visser et al. 2010 (1,872 nodes)"};
    static constexpr Spec physicsTargetNodeCountSpec{"physicsTargetNodeCount",
                                                     "1",
                                                     1900,
                                                     200,
                                                     20000,
                                                     "target number of physics nodes, rings + cecal cap",
                                                     "de Visser et al. 2010 (1,872 nodes)"};
    static constexpr Spec visualNodesPerRingSpec{"visualNodesPerRing",
                                                 "1",
                                                 64,
                                                 16,
                                                 256,
                                                 "visual vertices around each ring",
                                                 "de Visser et al. 2010 (~54,000 vertices)"};
    static constexpr Spec visualRingCountSpec{"visualRingCount",
                                              "1",
                                              850,
                                              100,
                                              4000,
                                              "visual rings along the colon (64 x 850 = 54,400 vertices)",
                                              "de Visser et al. 2010 (~54,000 vertices)"};

    double rectumLength = rectumLengthSpec.defaultValue;
    double sigmoidLength = sigmoidLengthSpec.defaultValue;
    double descendingLength = descendingLengthSpec.defaultValue;
    double splenicFlexureLength = splenicFlexureLengthSpec.defaultValue;
    double transverseLength = transverseLengthSpec.defaultValue;
    double hepaticFlexureLength = hepaticFlexureLengthSpec.defaultValue;
    double ascendingLength = ascendingLengthSpec.defaultValue;
    double cecumLength = cecumLengthSpec.defaultValue;

    double rectumDiameter = rectumDiameterSpec.defaultValue;
    double sigmoidDiameter = sigmoidDiameterSpec.defaultValue;
    double descendingDiameter = descendingDiameterSpec.defaultValue;
    double splenicFlexureDiameter = splenicFlexureDiameterSpec.defaultValue;
    double transverseDiameter = transverseDiameterSpec.defaultValue;
    double hepaticFlexureDiameter = hepaticFlexureDiameterSpec.defaultValue;
    double ascendingDiameter = ascendingDiameterSpec.defaultValue;
    double cecumDiameter = cecumDiameterSpec.defaultValue;

    double ascendingMobileFraction = ascendingMobileFractionSpec.defaultValue;
    double descendingMobile = descendingMobileSpec.defaultValue;
    double transverseMesenteryHeight = transverseMesenteryHeightSpec.defaultValue;
    double sigmoidMesenteryHeight = sigmoidMesenteryHeightSpec.defaultValue;
    double mobileColonMesenteryHeight = mobileColonMesenteryHeightSpec.defaultValue;
    double sigmoidRootLength = sigmoidRootLengthSpec.defaultValue;
    double sigmoidSweep = sigmoidSweepSpec.defaultValue;

    double haustralFoldDepth = haustralFoldDepthSpec.defaultValue;
    double haustralFoldSpacing = haustralFoldSpacingSpec.defaultValue;
    double taeniaDepth = taeniaDepthSpec.defaultValue;

    double physicsNodesPerRing = physicsNodesPerRingSpec.defaultValue;
    double physicsTargetNodeCount = physicsTargetNodeCountSpec.defaultValue;
    double visualNodesPerRing = visualNodesPerRingSpec.defaultValue;
    double visualRingCount = visualRingCountSpec.defaultValue;

    /// Every declared field, in declaration order.
    [[nodiscard]] static std::span<const params::Field<AnatomyParameters>> fields();

    /// Throws params::ParameterError naming the field, the value and the range.
    void validate() const;

    /// Length (m) and distended diameter (m) of one segment.
    [[nodiscard]] double length(Segment segment) const;
    [[nodiscard]] double diameter(Segment segment) const;
    [[nodiscard]] double totalLength() const;
    [[nodiscard]] bool isDescendingMobile() const { return descendingMobile >= 0.5; }
};

}  // namespace colonosim::geometry
