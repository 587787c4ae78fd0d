#pragma once
// Results on the geometry, for ParaView and other VTK readers: a VTK XML unstructured grid
// (.vtu, ASCII) of triangles with values per cell. Points are in the scene file's coordinates,
// in metres (the scene's origin added back in double); corners that are bitwise the same point
// are written once, so neighbouring cells share them. A double-sided surface's two sides are two
// cells on the same triangle (tell them apart by `side`).
//   solve:    one cell per element of the solution: `radiosity` B (W/m^2, RGB), `irradiance` H
//             (W/m^2, RGB: the light arriving, before reflection), `surface` (index into the
//             surface list in the file's comment lines), `side` (0 front, 1 back), `patch`,
//             `area` (m^2).
//   exchange: one cell per patch: `surface`, `side`, `area` (m^2), then its surface side's
//             `emissivity`, `temperature` (K), `net_flux` (W/m^2, positive when it loses heat),
//             `net_heat` (W: the cell's part, net_flux times its area, so that the cells of a
//             surface add up to the surface's net heat), `radiosity` and `irradiance` (W/m^2,
//             total), `to_space` (the share of its view that reaches no surface).

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "prepared/prepared_scene.h"
#include "thermal/radiative_exchange.h"

namespace rad {

struct VtuCellArray {
    std::string name;
    int components = 1;
    bool integer = false;        // written as Int32, else Float64
    std::vector<double> values;  // components per cell, cell after cell
};

struct VtuGrid {
    std::vector<glm::dvec3> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<VtuCellArray> cellData;
    std::vector<std::string> comments;  // one XML comment line each
};

void writeVtu(std::ostream& out, const VtuGrid& grid);

// The grids the commands write (see above).
VtuGrid solutionGrid(const PreparedScene& scene, const ElementMesh& elements, const std::vector<glm::vec3>& radiosity,
                     const std::vector<glm::vec3>& irradiance);
VtuGrid exchangeGrid(const PreparedScene& scene, const ExchangeEstimate& estimate);

}  // namespace rad
