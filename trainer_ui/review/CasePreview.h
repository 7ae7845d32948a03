#pragma once
/// \file
/// A generated case as the instructor reads it before saving or assigning:
/// the patient, indication, history and medication, bowel preparation, the
/// findings (lesions with segment, size and Paris class; diverticula;
/// colitis; adhesions) and the difficulty with its factors, as HTML.

#include "case_generator/Case.h"

#include <QString>

namespace colonosim::app {

[[nodiscard]] QString casePreviewHtml(const cases::Case& c);
/// One line: "Given Family, F 63 y, screening, difficulty 2/5, 1 lesion".
[[nodiscard]] QString caseTitle(const cases::Case& c);

}  // namespace colonosim::app
