#pragma once
// Radiative exchange between grey, diffuse, opaque surfaces by the net-radiation method
// (Siegel and Howell, "Thermal Radiation Heat Transfer", ch. 6): per surface its radiosity J
// (what leaves it, W / m^2) and irradiance H (what arrives),
//     H_i = sum_j F_ij J_j + F_i,env sigma T_env^4,
//     J_i = eps_i sigma T_i^4 + (1 - eps_i) H_i        where T_i is given,
//     J_i - H_i = q_i                                   where the flux q_i is imposed,
// one dense linear system in J. The net heat Q_i = A_i (J_i - H_i) is positive when the
// surface loses heat. The environment (what rays leave the scene toward) is black at T_env.

#include <vector>

#include "thermal/thermal_properties.h"

namespace rad {

inline constexpr double kStefanBoltzmann = 5.670374419e-8;  // W / m^2 / K^4 (CODATA 2018, exact)

struct ExchangeProblem {
    std::vector<double> area;                  // m^2
    std::vector<std::vector<double>> factor;   // F_ij, n x n, row i from surface i
    std::vector<SurfaceCondition> conditions;  // per surface
    double environmentTemperature = 0.0;       // K
    // F_i,env = 1 - sum_j F_ij (at least 0): what of i's view leaves the scene.
    double escape(std::size_t i) const;
};

struct ExchangeSolution {
    std::vector<double> radiosity, irradiance;  // J, H, W / m^2
    std::vector<double> temperature;            // K: the given ones, and those solved for
    std::vector<double> netFlux, netHeat;       // J - H (W / m^2), A (J - H) (W)
    double toEnvironment = 0.0;                 // W: sum A_i F_i,env (J_i - sigma T_env^4)
};

// Throws InputError when the system is singular (an enclosure in which every surface has an
// imposed flux fixes no temperature) or a solved temperature would be negative (the imposed
// fluxes take out more than arrives).
ExchangeSolution solveNetRadiation(const ExchangeProblem& problem);

// Gebhart's exchange factors: G_ij, the fraction of the power surface i emits that surface j
// absorbs, after any number of diffuse reflections: G = (I - F diag(1 - eps))^-1 F diag(eps).
// In a closed scene every row sums to 1; eps_i A_i G_ij = eps_j A_j G_ji when F is reciprocal.
std::vector<std::vector<double>> exchangeFactors(const ExchangeProblem& problem);

}  // namespace rad
