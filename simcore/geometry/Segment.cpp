#include "simcore/geometry/Segment.h"

namespace colonosim::geometry {

std::string_view segmentName(Segment segment)
{
    switch (segment) {
    case Segment::Rectum: return "rectum";
    case Segment::Sigmoid: return "sigmoid";
    case Segment::Descending: return "descending";
    case Segment::SplenicFlexure: return "splenic_flexure";
    case Segment::Transverse: return "transverse";
    case Segment::HepaticFlexure: return "hepatic_flexure";
    case Segment::Ascending: return "ascending";
    case Segment::Cecum: return "cecum";
    }
    return "unknown";
}

}  // namespace colonosim::geometry
