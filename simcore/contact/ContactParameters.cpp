#include "simcore/contact/ContactParameters.h"

#include <array>

namespace colonosim::contact {

namespace {
using P = ContactParameters;
constexpr std::array<Field<P>, 17> kContactFields{{
    {&P::stiffnessSpec, &P::contactStiffness},
    {&P::dampingSpec, &P::contactDamping},
    {&P::frictionSpec, &P::frictionCoefficient},
    {&P::stickVelocitySpec, &P::stickVelocity},
    {&P::passesSpec, &P::couplingPasses},
    {&P::sweepsSpec, &P::couplingSweeps},
    {&P::sweepToleranceSpec, &P::sweepTolerance},
    {&P::passToleranceSpec, &P::passSweepTolerance},
    {&P::prefixSweepsSpec, &P::prefixSweeps},
    {&P::accelerationSpec, &P::sweepAcceleration},
    {&P::elementPointsSpec, &P::elementPoints},
    {&P::sideNormalsSpec, &P::sideNormals},
    {&P::stickingFrictionSpec, &P::stickingFriction},
    {&P::pleatSearchSpec, &P::pleatSearch},
    {&P::spinFrictionSpec, &P::spinFriction},
    {&P::relaxationSpec, &P::loadRelaxation},
    {&P::stepLimitSpec, &P::stepLimit},
}};
}  // namespace

std::span<const Field<ContactParameters>> ContactParameters::fields()
{
    return kContactFields;
}

void ContactParameters::validate() const
{
    params::validateFields<ContactParameters>("contact", kContactFields, *this);
}

}  // namespace colonosim::contact
