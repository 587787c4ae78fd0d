#include "thermal/thermal_properties.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "scene/property_materials.h"
#include "util/csv_fields.h"
#include "util/error.h"

namespace rad {

std::vector<SurfaceCondition> readThermalProperties(const std::string& path, const std::vector<std::string>& surfaces,
                                                    const ThermalDefaults& defaults) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot open the properties file");
    std::map<std::string, std::size_t> index;
    for (std::size_t s = 0; s < surfaces.size(); ++s) index.emplace(surfaces[s], s);
    std::vector<std::optional<SurfaceCondition>> given(surfaces.size());

    std::string line;
    std::size_t number = 0;
    int surfaceColumn = -1, emissivityColumn = -1, temperatureColumn = -1, fluxColumn = -1;
    bool header = true;
    while (std::getline(in, line)) {
        ++number;
        const auto fail = [&](const std::string& problem) {
            throw FileError(path, "line " + std::to_string(number) + ": " + problem);
        };
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::vector<std::string> fields = csvFields(line);
        if (header) {
            header = false;
            for (std::size_t c = 0; c < fields.size(); ++c) {
                const std::string& name = fields[c];
                int* column = name == "surface"       ? &surfaceColumn
                              : name == "emissivity"  ? &emissivityColumn
                              : name == "temperature" ? &temperatureColumn
                              : name == "heat_flux"   ? &fluxColumn
                                                      : nullptr;
                if (!column && isMaterialColumn(name)) continue;  // solve's and pathtrace's: the same file serves all
                if (!column)
                    fail("unknown column '" + name + "' (the columns are surface, emissivity, temperature, heat_flux; " +
                         kMaterialColumnsListed + ")");
                if (*column >= 0) fail("column '" + name + "' appears twice");
                *column = static_cast<int>(c);
            }
            if (surfaceColumn < 0) fail("the header has no 'surface' column");
            if (emissivityColumn < 0) fail("the header has no 'emissivity' column");
            if (temperatureColumn < 0 && fluxColumn < 0)
                fail("the header has neither a 'temperature' nor a 'heat_flux' column");
            continue;
        }
        const auto columns =
            static_cast<std::size_t>(std::max({surfaceColumn, emissivityColumn, temperatureColumn, fluxColumn})) + 1;
        if (fields.size() < columns)
            fail("has " + std::to_string(fields.size()) + " fields, fewer than the header's " +
                 std::to_string(columns));
        const std::string& name = fields[static_cast<std::size_t>(surfaceColumn)];
        const auto found = index.find(name);
        if (found == index.end())
            fail("the scene has no surface side named '" + name + "' (names as viewfactors gives them)");
        if (given[found->second]) fail("surface '" + name + "' is listed twice");
        SurfaceCondition condition;
        const auto emissivity = csvNumber(fields[static_cast<std::size_t>(emissivityColumn)], fail, "emissivity");
        if (!emissivity) fail("surface '" + name + "' has no emissivity");
        if (!(*emissivity > 0.0 && *emissivity <= 1.0))
            fail("the emissivity of '" + name + "' is " + fields[static_cast<std::size_t>(emissivityColumn)] +
                 ", outside (0, 1]");
        condition.emissivity = *emissivity;
        const auto temperature =
            temperatureColumn >= 0 ? csvNumber(fields[static_cast<std::size_t>(temperatureColumn)], fail, "temperature")
                                   : std::nullopt;
        const auto flux =
            fluxColumn >= 0 ? csvNumber(fields[static_cast<std::size_t>(fluxColumn)], fail, "heat flux") : std::nullopt;
        if (temperature && flux) fail("surface '" + name + "' has both a temperature and a heat flux: give one");
        if (!temperature && !flux) fail("surface '" + name + "' has neither a temperature nor a heat flux");
        if (temperature) {
            const double t = temperature.value_or(0.0);
            if (t < 0.0) fail("the temperature of '" + name + "' is negative (kelvin)");
            if (t > 1e9) fail("the temperature of '" + name + "' is above 1e9 K");
            condition.temperature = t;
        } else {
            const double q = flux.value_or(0.0);
            if (std::fabs(q) > 1e30) fail("the heat flux of '" + name + "' is beyond 1e30 W/m^2");
            condition.temperatureGiven = false;
            condition.heatFlux = q;
        }
        given[found->second] = condition;
    }
    if (header)
        throw FileError(path, "the properties file is empty (it needs a header: surface,emissivity,temperature)");

    std::vector<SurfaceCondition> conditions(surfaces.size());
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        if (given[s]) {
            conditions[s] = *given[s];
            continue;
        }
        if (!defaults.emissivity || !defaults.temperature)
            throw InputError("surface '" + surfaces[s] + "' is not listed in " + path +
                             " and --default-emissivity and --default-temperature are not both given");
        conditions[s].emissivity = *defaults.emissivity;
        conditions[s].temperature = *defaults.temperature;
    }
    return conditions;
}

}  // namespace rad
