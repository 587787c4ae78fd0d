#include "thermal/net_radiation.h"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "util/error.h"

namespace rad {

double ExchangeProblem::escape(std::size_t i) const {
    double sum = 0.0;
    for (double f : factor[i]) sum += f;
    return std::max(0.0, 1.0 - sum);
}

ExchangeSolution solveNetRadiation(const ExchangeProblem& problem) {
    const std::size_t n = problem.area.size();
    // Without a given temperature, and with nothing leaving to the environment, the fluxes fix
    // the radiosities only up to a constant: refused outright, since estimated factors leave the
    // matrix a rounding error away from singular, which no pivot test can tell from a fact.
    bool anchored = false;
    for (std::size_t i = 0; i < n && !anchored; ++i)
        anchored = problem.conditions[i].temperatureGiven || problem.escape(i) > 1e-9;
    if (n > 0 && !anchored)
        throw InputError(
            "the heat exchange has no unique solution: in a closed scene at least one surface needs a "
            "temperature (with only imposed fluxes, temperatures are fixed up to a constant)");
    const double environment = kStefanBoltzmann * std::pow(problem.environmentTemperature, 4);
    Eigen::MatrixXd a = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    Eigen::VectorXd b(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const SurfaceCondition& c = problem.conditions[i];
        const auto r = static_cast<Eigen::Index>(i);
        // Given T: J_i - (1 - eps_i) sum_j F_ij J_j = eps_i sigma T_i^4 + (1 - eps_i) F_ie sigma T_env^4.
        // Given q: J_i - sum_j F_ij J_j = q_i + F_ie sigma T_env^4.
        const double keep = c.temperatureGiven ? 1.0 - c.emissivity : 1.0;
        for (std::size_t j = 0; j < n; ++j) a(r, static_cast<Eigen::Index>(j)) -= keep * problem.factor[i][j];
        b(r) = c.temperatureGiven ? c.emissivity * kStefanBoltzmann * std::pow(c.temperature, 4) +
                                        keep * problem.escape(i) * environment
                                  : c.heatFlux + problem.escape(i) * environment;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
    lu.setThreshold(1e-10);
    if (!lu.isInvertible())
        throw InputError(
            "the heat exchange has no unique solution: in a closed scene at least one surface needs a "
            "temperature (with only imposed fluxes, temperatures are fixed up to a constant)");
    const Eigen::VectorXd j = lu.solve(b);

    ExchangeSolution s;
    s.radiosity.resize(n);
    s.irradiance.resize(n);
    s.temperature.resize(n);
    s.netFlux.resize(n);
    s.netHeat.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        double h = problem.escape(i) * environment;
        for (std::size_t k = 0; k < n; ++k) h += problem.factor[i][k] * j(static_cast<Eigen::Index>(k));
        const SurfaceCondition& c = problem.conditions[i];
        s.radiosity[i] = j(static_cast<Eigen::Index>(i));
        s.irradiance[i] = h;
        s.netFlux[i] = s.radiosity[i] - h;
        s.netHeat[i] = problem.area[i] * s.netFlux[i];
        if (c.temperatureGiven) {
            s.temperature[i] = c.temperature;
        } else {
            // J = eps sigma T^4 + (1 - eps) H.
            const double emitted = (s.radiosity[i] - (1.0 - c.emissivity) * h) / c.emissivity;
            if (emitted < -1e-9 * std::max(std::fabs(s.radiosity[i]), 1e-30))
                throw InputError(
                    "the imposed heat fluxes have no solution with temperatures >= 0 K: a surface would "
                    "have to emit " +
                    std::to_string(emitted) + " W/m^2");
            s.temperature[i] = std::pow(std::max(0.0, emitted) / kStefanBoltzmann, 0.25);
        }
        s.toEnvironment += problem.area[i] * problem.escape(i) * (s.radiosity[i] - environment);
    }
    return s;
}

std::vector<std::vector<double>> exchangeFactors(const ExchangeProblem& problem) {
    const std::size_t n = problem.area.size();
    const auto size = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd a = Eigen::MatrixXd::Identity(size, size), rhs(size, size);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const double f = problem.factor[i][j];
            a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) -=
                f * (1.0 - problem.conditions[j].emissivity);
            rhs(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = f * problem.conditions[j].emissivity;
        }
    const Eigen::MatrixXd g = a.fullPivLu().solve(rhs);
    std::vector<std::vector<double>> out(n, std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) out[i][j] = g(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    return out;
}

}  // namespace rad
