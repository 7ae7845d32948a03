#pragma once
/// \file
/// The patient of a report command's seed: seed 0 is the default colon with
/// the default settings; any other seed is the generated case of that seed,
/// its anatomy and its procedure settings (lesions, adhesions), drawn under
/// `constraints` when given (the generator's rejection sampling, so the same
/// seed and constraints give the same patient).

#include "case_generator/CaseGenerator.h"
#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/ProcedureLoop.h"

#include <cstdint>

namespace colonosim::bench {

struct Patient {
    geometry::AnatomyParameters anatomy;
    procedure::ProcedureSettings settings;
};

inline Patient patientFromSeed(std::uint64_t seed, const cases::Constraints& constraints = {})
{
    Patient patient;
    if (seed != 0) {
        const cases::SceneSpec scene = cases::toScene(cases::CaseGenerator().generate(seed, constraints));
        patient.anatomy = scene.anatomy;
        patient.settings = cases::procedureSettings(scene);
    }
    return patient;
}

}  // namespace colonosim::bench
