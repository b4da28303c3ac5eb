#include "core/softbody/integrators.h"

namespace granota {

std::optional<Integrator> parseIntegrator(std::string_view name)
{
    if (name == "euler")
        return Integrator::ExplicitEuler;
    if (name == "semi-implicit-euler")
        return Integrator::SemiImplicitEuler;
    if (name == "verlet")
        return Integrator::Verlet;
    if (name == "rk4")
        return Integrator::Rk4;
    return std::nullopt;
}

std::string integratorName(Integrator i)
{
    switch (i) {
    case Integrator::ExplicitEuler: return "euler";
    case Integrator::SemiImplicitEuler: return "semi-implicit-euler";
    case Integrator::Verlet: return "verlet";
    case Integrator::Rk4: return "rk4";
    }
    return {};
}

int evaluationsPerStep(Integrator i) { return i == Integrator::Rk4 ? 4 : 1; }

} // namespace granota
