#include "case_generator/EnvironmentSampler.h"

#include "case_generator/Quantity.h"

#include <vector>

namespace colonosim::cases {

int preparationClass(int right, int transverse, int left)
{
    const int total = right + transverse + left;
    if (right >= 2 && transverse >= 2 && left >= 2) {
        return 0;
    }
    if (total >= 3 && total <= 5) {
        return 1;
    }
    if (total <= 2) {
        return 2;
    }
    return 3;
}

namespace {
/// The score triples of each class, as (right, transverse, left) in base 4.
const std::array<std::vector<int>, 4>& triplesByClass()
{
    static const std::array<std::vector<int>, 4> table = [] {
        std::array<std::vector<int>, 4> t;
        for (int code = 0; code < 64; ++code) {
            t[preparationClass(code / 16, (code / 4) % 4, code % 4)].push_back(code);
        }
        return t;
    }();
    return table;
}
}  // namespace

void sampleEnvironment(const Statistics& stats, Random& random, Environment& environment)
{
    const std::vector<int>& triples = triplesByClass()[random.choose(stats.preparationClassShare)];
    const int code = triples[random.below(triples.size())];
    const int scores[kNumBowelRegions] = {code / 16, (code / 4) % 4, code % 4};
    for (int r = 0; r < kNumBowelRegions; ++r) {
        Preparation& p = environment.preparation[r];
        p.boston = scores[r];
        const Range& stool = stats.residualStool[p.boston];
        const Range& fluid = stats.residualFluid[p.boston];
        p.residualStool = quantity::residualStool.quantise(random.uniform(stool.lo, stool.hi));
        p.residualFluid = quantity::residualFluid.quantise(random.uniform(fluid.lo, fluid.hi));
    }
    environment.insufflationCompliance =
        quantity::insufflationCompliance.quantise(random.uniform(stats.compliance.lo, stats.compliance.hi));
    environment.insufflationPressure =
        quantity::insufflationPressure.quantise(stats.referencePressure / environment.insufflationCompliance);
}

}  // namespace colonosim::cases
