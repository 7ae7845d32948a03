#include "case_generator/PathologySampler.h"

#include "case_generator/DeterministicMath.h"
#include "case_generator/Quantity.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace colonosim::cases {

namespace {

using S = Segment;
const std::vector<Segment> kProximal{S::Cecum, S::Ascending, S::HepaticFlexure, S::Transverse,
                                     S::SplenicFlexure};
const std::vector<Segment> kDistal{S::Descending, S::Sigmoid, S::Rectum};

double segmentLength(const Case& c, Segment s)
{
    return c.anatomy.length[static_cast<int>(s)];
}

WallPlace placeIn(const Case& c, const std::vector<Segment>& segments, Random& random)
{
    std::vector<double> weights;
    weights.reserve(segments.size());
    for (const Segment s : segments) {
        weights.push_back(segmentLength(c, s));
    }
    WallPlace place;
    place.segment = segments[random.choose(weights)];
    place.position = quantity::position.quantise(random.uniform() * segmentLength(c, place.segment));
    place.clockAngle = random.integer(0, 359) * quantity::clockAngle.siPerUnit;
    return place;
}

/// Size in mm of class 0 (<= 5), 1 (6-9) or 2 (>= 10).
int sizeOfClass(const Statistics& stats, int sizeClass, Random& random)
{
    if (sizeClass < 2) {
        return stats.smallSizes[sizeClass][random.choose(stats.smallSizeShare[sizeClass])];
    }
    const IntRange& r = stats.largeSizeRanges[random.choose(stats.largeSizeShare)];
    return random.integer(r.lo, r.hi);
}

int sizeClassOf(double sizeMm)
{
    return sizeMm <= 5.5 ? 0 : (sizeMm <= 9.5 ? 1 : 2);
}

Lesion adenoma(const Statistics& stats, const Case& c, bool proximal, Random& random)
{
    Lesion l;
    l.place = placeIn(c, proximal ? kProximal : kDistal, random);
    const int sizeClass = static_cast<int>(random.choose(stats.sizeClassShare));
    l.size = sizeOfClass(stats, sizeClass, random) * 0.001;
    if (random.chance(stats.advancedHistology[sizeClass])) {
        constexpr Histology advanced[] = {Histology::Tubulovillous, Histology::Villous,
                                          Histology::TubularHighGrade};
        l.histology = advanced[random.choose(stats.advancedHistologyShare)];
    } else {
        l.histology = Histology::TubularLowGrade;
    }
    switch (random.choose(stats.morphologyShare)) {
    case 0: l.paris = random.choose(stats.sessileParis) == 0 ? Paris::Is : Paris::Isp; break;
    case 1: l.paris = Paris::Ip; break;
    case 2:
        if (sizeClass == 2) {
            l.paris = random.choose(stats.lstParis) == 0 ? Paris::LstGranular : Paris::LstNonGranular;
        } else {
            l.paris = random.choose(stats.flatParis) == 0 ? Paris::IIa : Paris::IIb;
        }
        break;
    default: l.paris = Paris::IIc; break;
    }
    l.stiffness = random.uniform(stats.adenomaStiffness.lo, stats.adenomaStiffness.hi);
    return l;
}

/// Zero-truncated Poisson by its inverse CDF.
int adenomaCount(const Statistics& stats, Random& random)
{
    const double lambda = stats.adenomaCountLambda;
    const double u = random.uniform() * (1.0 - detmath::exp(-lambda));
    double p = detmath::exp(-lambda);
    double cumulative = 0.0;
    for (int k = 1; k < 60; ++k) {
        p = p * lambda / k;
        cumulative += p;
        if (u < cumulative) {
            return k;
        }
    }
    return 60;
}

void addAdenomas(const Statistics& stats, Random& random, Case& c)
{
    const int n = adenomaCount(stats, random);
    const double lambda = stats.adenomaCountLambda;
    const double single = lambda * detmath::exp(-lambda) / (1.0 - detmath::exp(-lambda));
    const double proximalShare = stats.onlyProximal / (stats.onlyProximal + stats.onlyDistal);
    const bool both = n >= 2 && random.chance(stats.bothRegions / (1.0 - single));
    const bool allProximal = !both && random.chance(proximalShare);
    for (int i = 0; i < n; ++i) {
        // In a patient with both: the first proximal, the second distal, the rest either, evenly.
        const bool proximal = both ? (i == 0 || (i > 1 && random.chance(0.5))) : allProximal;
        c.lesions.push_back(adenoma(stats, c, proximal, random));
    }
}

Lesion serrated(const Statistics& stats, const Case& c, Histology histology, Random& random)
{
    Lesion l;
    l.histology = histology;
    bool proximal = false;
    const std::array<double, 3>* sizes = nullptr;
    const Statistics::ParisMix* paris = nullptr;
    switch (histology) {
    case Histology::SessileSerrated:
        proximal = random.chance(stats.sessileSerratedProximal);
        sizes = &stats.sessileSerratedSize;
        paris = &stats.sessileSerratedParis;
        break;
    case Histology::TraditionalSerrated:
        proximal = !random.chance(stats.traditionalDistal);
        sizes = &stats.traditionalSize;
        paris = &stats.traditionalParis;
        break;
    default:
        proximal = !random.chance(stats.hyperplasticDistal);
        sizes = &stats.hyperplasticSize;
        paris = &stats.hyperplasticParis;
        break;
    }
    l.place = placeIn(c, proximal ? kProximal : kDistal, random);
    l.size = sizeOfClass(stats, static_cast<int>(random.choose(*sizes)), random) * 0.001;
    l.paris = paris->paris[random.choose(paris->share)];
    l.stiffness = random.uniform(stats.serratedStiffness.lo, stats.serratedStiffness.hi);
    return l;
}

Lesion carcinoma(const Statistics& stats, const Case& c, Random& random)
{
    Lesion l;
    l.histology = Histology::Adenocarcinoma;
    l.place = placeIn(c, random.chance(stats.cancerProximal) ? kProximal : kDistal, random);
    l.size = random.integer(stats.cancerSize.lo, stats.cancerSize.hi) * 0.001;
    l.paris = stats.cancerParis[random.choose(stats.cancerParisShare)];
    l.stiffness = random.uniform(stats.carcinomaStiffness.lo, stats.carcinomaStiffness.hi);
    return l;
}

Lesion lipoma(const Statistics& stats, const Case& c, Random& random)
{
    Lesion l;
    l.histology = Histology::Lipoma;
    // ascending, transverse, ileocecal valve, cecum, descending, rectosigmoid
    const std::size_t where = random.choose(stats.lipomaLocationShare);
    constexpr Segment segments[] = {S::Ascending, S::Transverse, S::Cecum,
                                    S::Cecum,     S::Descending, S::Sigmoid};
    l.place.segment = segments[where];
    double along = random.uniform();
    if (where == 2 || where == 5) {
        along *= 0.2;  // the valve and the rectosigmoid junction sit at these segments' anal ends
    }
    l.place.position = quantity::position.quantise(along * segmentLength(c, l.place.segment));
    l.place.clockAngle = random.integer(0, 359) * quantity::clockAngle.siPerUnit;
    int mm = 0;
    do {
        mm = static_cast<int>(
            std::floor(detmath::exp(random.normal(stats.lipomaSize.mu, stats.lipomaSize.sigma)) + 0.5));
    } while (mm < stats.lipomaSizeRange.lo || mm > stats.lipomaSizeRange.hi);
    l.size = mm * 0.001;
    l.paris = random.chance(stats.lipomaPedunculated) ? Paris::Ip : Paris::Is;
    l.stiffness = random.uniform(stats.lipomaStiffness.lo, stats.lipomaStiffness.hi);
    return l;
}

void addDiverticula(const Statistics& stats, Random& random, Case& c)
{
    const double any = stats.diverticulosisRate(c.patient.age);
    if (!random.chance(any)) {
        return;
    }
    const bool many = random.chance(stats.diverticulosisManyRate(c.patient.age) / any);
    const int n = many ? random.integer(11, 40) : random.integer(1, 10);
    const std::vector<Segment> regions[] = {
        {S::Sigmoid}, {S::Descending, S::SplenicFlexure}, {S::Transverse}, {S::Ascending, S::HepaticFlexure}};
    for (int i = 0; i < n; ++i) {
        Diverticulum d;
        d.place = placeIn(c, regions[random.choose(stats.diverticulumRegionShare)], random);
        d.diameter = quantity::diverticulumDiameter.quantise(
            random.uniform(stats.diverticulumDiameter.lo, stats.diverticulumDiameter.hi));
        c.diverticula.push_back(d);
    }
}

}  // namespace

void describeAppearance(const Statistics& stats, Lesion& l)
{
    const double mm = l.size * 1000.0;
    switch (l.histology) {
    case Histology::Hyperplastic:
    case Histology::SessileSerrated: l.colour = Colour::Pale; break;
    case Histology::Lipoma: l.colour = Colour::Yellowish; break;
    case Histology::TubularLowGrade: l.colour = mm >= 10 ? Colour::Reddish : Colour::Isochromatic; break;
    default: l.colour = Colour::Reddish; break;
    }
    if (l.paris == Paris::Type2) {
        l.surface = Surface::Ulcerated;
    } else if (l.paris == Paris::LstGranular) {
        l.surface = Surface::Granular;
    } else if (mm >= 20 && l.histology != Histology::Lipoma) {
        l.surface = Surface::Lobulated;
    } else {
        l.surface = Surface::Smooth;
    }
    l.niceType = l.histology == Histology::Adenocarcinoma ? 3 : (isAdenoma(l.histology) ? 2 : 1);
    const double base = stats.missRateBySize[sizeClassOf(mm)];
    double ratio = stats.missOddsRatio[1];  // sessile, also for advanced cancers
    if (l.paris == Paris::Ip) {
        ratio = stats.missOddsRatio[0];
    } else if (l.paris == Paris::IIc) {
        ratio = stats.missOddsRatio[3];
    } else if (isFlatOrDepressed(l.paris)) {
        ratio = stats.missOddsRatio[2];
    }
    const double odds = base / (1.0 - base) * ratio;
    l.missRate = quantity::missRate.quantise(odds / (1.0 + odds));
    l.stiffness = quantity::lesionStiffness.quantise(l.stiffness);
}

void samplePathology(const Statistics& stats, Random& random, Case& c)
{
    const Sex sex = c.patient.sex;
    const int age = c.patient.age;
    c.lesions.clear();
    c.diverticula.clear();
    if (random.chance(stats.adenomaRate(sex, age))) {
        addAdenomas(stats, random, c);
    }
    if (random.chance(stats.cancerRate(sex, age))) {
        c.lesions.push_back(carcinoma(stats, c, random));
    }
    if (random.chance(stats.sessileSerrated.of(sex))) {
        c.lesions.push_back(serrated(stats, c, Histology::SessileSerrated, random));
    }
    if (random.chance(stats.traditionalSerrated)) {
        c.lesions.push_back(serrated(stats, c, Histology::TraditionalSerrated, random));
    }
    if (random.chance(stats.hyperplasticRate(sex))) {
        c.lesions.push_back(serrated(stats, c, Histology::Hyperplastic, random));
    }
    if (random.chance(stats.lipoma.value)) {
        c.lesions.push_back(lipoma(stats, c, random));
    }
    for (Lesion& l : c.lesions) {
        describeAppearance(stats, l);
    }
    addDiverticula(stats, random, c);
    c.colitis = ColitisExtent::None;
    if (random.chance(stats.colitis.value)) {
        c.colitis = static_cast<ColitisExtent>(1 + random.choose(stats.colitisExtentShare));
    }
    const double risk = stats.hemorrhoids.value *
                        detmath::exp(detmath::log(stats.hemorrhoidRiskPerBmi) * (c.patient.bmi - 25.0)) /
                        stats.hemorrhoidNormaliser(sex);
    c.hemorrhoidGrade = random.chance(std::min(1.0, risk))
                            ? 1 + static_cast<int>(random.choose(stats.hemorrhoidGradeShare))
                            : 0;
}

void fitLesionsToLumen(Case& c)
{
    for (Lesion& l : c.lesions) {
        const double circumference = std::numbers::pi * c.anatomy.diameter[static_cast<int>(l.place.segment)];
        if (l.size > circumference) {
            l.size = std::floor(circumference * 1000.0) * 0.001;
        }
    }
}

}  // namespace colonosim::cases
