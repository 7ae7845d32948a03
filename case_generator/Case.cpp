#include "case_generator/Case.h"

namespace colonosim::cases {

bool isAdenoma(Histology histology)
{
    return histology == Histology::TubularLowGrade || histology == Histology::TubularHighGrade ||
           histology == Histology::Tubulovillous || histology == Histology::Villous;
}

bool isSerrated(Histology histology)
{
    return histology == Histology::Hyperplastic || histology == Histology::SessileSerrated ||
           histology == Histology::TraditionalSerrated;
}

bool isAdvancedAdenoma(const Lesion& lesion)
{
    return isAdenoma(lesion.histology) &&
           (lesion.size >= 0.0095 || lesion.histology != Histology::TubularLowGrade);
}

bool isFlatOrDepressed(Paris paris)
{
    return paris == Paris::IIa || paris == Paris::IIb || paris == Paris::IIc || paris == Paris::LstGranular ||
           paris == Paris::LstNonGranular;
}

bool isProximal(Segment segment)
{
    return segment == Segment::Cecum || segment == Segment::Ascending || segment == Segment::HepaticFlexure ||
           segment == Segment::Transverse || segment == Segment::SplenicFlexure;
}

BowelRegion bowelRegion(Segment segment)
{
    switch (segment) {
    case Segment::Cecum:
    case Segment::Ascending: return BowelRegion::Right;
    case Segment::HepaticFlexure:
    case Segment::Transverse:
    case Segment::SplenicFlexure: return BowelRegion::Transverse;
    default: return BowelRegion::Left;
    }
}

}  // namespace colonosim::cases
