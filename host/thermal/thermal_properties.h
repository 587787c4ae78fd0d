#pragma once
// The thermal boundary conditions of `radiosity exchange`: per surface side, its emissivity and
// either its temperature or the heat flux imposed on it (then its temperature is solved for).
// Read from a CSV file whose header names the columns `surface`, `emissivity`, and
// `temperature` or `heat_flux` (or both, each row filling exactly one); surfaces it does not
// list take the defaults, or are refused when there are none.

#include <optional>
#include <string>
#include <vector>

namespace rad {

struct SurfaceCondition {
    double emissivity = 1.0;  // in (0, 1]
    bool temperatureGiven = true;
    double temperature = 0.0;  // K, >= 0, when given
    double heatFlux = 0.0;     // W / m^2 imposed (net loss by radiation), when not
};

struct ThermalDefaults {
    std::optional<double> emissivity;
    std::optional<double> temperature;
};

// One condition per name in `surfaces` (as `viewfactors` names surface sides). Throws FileError
// naming the file, the line and the problem: a missing column, an unknown or repeated surface,
// an emissivity outside (0, 1], a temperature outside [0, 1e9] K, a flux that is not a finite
// number within 1e30 W / m^2, a row with both or neither of temperature and heat flux; and InputError for a surface
// neither listed nor covered by the defaults.
std::vector<SurfaceCondition> readThermalProperties(const std::string& path, const std::vector<std::string>& surfaces,
                                                    const ThermalDefaults& defaults);

}  // namespace rad
