#include "core/softbody/integrators.h"

#include "core/base/enum_names.h"

namespace granota {

namespace {

constexpr std::array<EnumName<Integrator>, 4> kIntegratorNames{{
    {Integrator::ExplicitEuler, "euler"},
    {Integrator::SemiImplicitEuler, "semi-implicit-euler"},
    {Integrator::Verlet, "verlet"},
    {Integrator::Rk4, "rk4"},
}};

} // namespace

std::optional<Integrator> parseIntegrator(std::string_view name) { return parseName(kIntegratorNames, name); }

std::string integratorName(Integrator i) { return std::string(nameOf(kIntegratorNames, i)); }

int evaluationsPerStep(Integrator i) { return i == Integrator::Rk4 ? 4 : 1; }

} // namespace granota
