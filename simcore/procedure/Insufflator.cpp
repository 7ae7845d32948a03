#include "simcore/procedure/Insufflator.h"

#include <array>

namespace colonosim::procedure {

namespace {
using I = InsufflatorParameters;
constexpr std::array<params::Field<I>, 2> kInsufflatorFields{{
    {&I::pressureRateSpec, &I::pressureRate},
    {&I::maxPressureSpec, &I::maxPressure},
}};
}  // namespace

std::span<const params::Field<InsufflatorParameters>> InsufflatorParameters::fields()
{
    return kInsufflatorFields;
}

void InsufflatorParameters::validate() const
{
    params::validateFields<InsufflatorParameters>("insufflator", kInsufflatorFields, *this);
}

}  // namespace colonosim::procedure
