#include "io/vtu_file.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>

#include "util/error.h"

namespace rad {
namespace {

std::string number(double value, int digits) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

// An XML comment may not hold "--" nor end in "-".
std::string commentText(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    std::string out;
    for (char c : text) {
        if (c == '-' && !out.empty() && out.back() == '-') out += ' ';
        out += c;
    }
    if (!out.empty() && out.back() == '-') out += ' ';
    return out;
}

// Points welded where bitwise equal (positions relative to the scene's origin, as the mesh keeps
// them), written in the scene file's coordinates.
class PointTable {
public:
    PointTable(VtuGrid& grid, const glm::dvec3& origin) : grid_(grid), origin_(origin) {}
    void triangle(const std::array<glm::vec3, 3>& corners) {
        std::array<std::uint32_t, 3> t{};
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = corners[k];
            const auto key = std::make_tuple(p.x, p.y, p.z);
            const auto [at, added] = index_.try_emplace(key, static_cast<std::uint32_t>(grid_.points.size()));
            if (added) grid_.points.push_back(origin_ + glm::dvec3(p));
            t[k] = at->second;
        }
        grid_.triangles.push_back(t);
    }

private:
    VtuGrid& grid_;
    glm::dvec3 origin_;
    std::map<std::tuple<float, float, float>, std::uint32_t> index_;
};

// The grids below hold a few arrays: room is kept for them first, so the references stay valid.
constexpr std::size_t kMostArrays = 16;

VtuCellArray& cellArray(VtuGrid& grid, std::string name, int components = 1, bool integer = false) {
    if (grid.cellData.size() >= kMostArrays) throw std::logic_error("VTU grid: too many cell arrays");
    grid.cellData.reserve(kMostArrays);
    grid.cellData.push_back({std::move(name), components, integer, {}});
    return grid.cellData.back();
}

void surfaceComments(VtuGrid& grid, const Mesh& mesh) {
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s)
        grid.comments.push_back("surface " + std::to_string(s) + ": " + mesh.surfaces[s].name);
}

}  // namespace

void writeVtu(std::ostream& out, const VtuGrid& grid) {
    const std::size_t cells = grid.triangles.size();
    for (const VtuCellArray& a : grid.cellData)
        if (a.values.size() != cells * static_cast<std::size_t>(a.components))
            throw std::logic_error("VTU cell array " + a.name + " does not match the cells");
    out << "<?xml version=\"1.0\"?>\n";
    for (const std::string& c : grid.comments) out << "<!-- " << commentText(c) << " -->\n";
    out << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
        << grid.points.size() << "\" NumberOfCells=\"" << cells << "\">\n<CellData>\n";
    for (const VtuCellArray& a : grid.cellData) {
        out << "<DataArray type=\"" << (a.integer ? "Int32" : "Float64") << "\" Name=\"" << a.name
            << "\" NumberOfComponents=\"" << a.components << "\" format=\"ascii\">\n";
        for (std::size_t c = 0; c < cells; ++c) {
            for (int k = 0; k < a.components; ++k) {
                const double v = a.values[c * a.components + k];
                out << (k ? " " : "") << (a.integer ? std::to_string(static_cast<long long>(v)) : number(v, 9));
            }
            out << '\n';
        }
        out << "</DataArray>\n";
    }
    out << "</CellData>\n<Points>\n<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (const glm::dvec3& p : grid.points) out << number(p.x, 12) << ' ' << number(p.y, 12) << ' ' << number(p.z, 12) << '\n';
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : grid.triangles) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < cells; ++c) out << 3 * (c + 1) << (c + 1 == cells || (c + 1) % 16 == 0 ? "\n" : " ");
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < cells; ++c) out << "5" << (c + 1 == cells || (c + 1) % 32 == 0 ? "\n" : " ");
    out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

VtuGrid solutionGrid(const PreparedScene& scene, const ElementMesh& elements, const std::vector<glm::vec3>& radiosity,
                     const std::vector<glm::vec3>& irradiance) {
    const Mesh& mesh = scene.mesh();
    VtuGrid grid;
    grid.comments.push_back("radiosity solve: one cell per element; radiosity and irradiance in W/m^2 (RGB)");
    surfaceComments(grid, mesh);
    PointTable points(grid, scene.scene().origin);
    const std::vector<Element>& all = elements.elements();
    VtuCellArray& b = cellArray(grid, "radiosity", 3);
    for (std::size_t e = 0; e < all.size(); ++e)
        for (int k = 0; k < 3; ++k) b.values.push_back(radiosity[e][k]);
    if (irradiance.size() == all.size()) {
        VtuCellArray& h = cellArray(grid, "irradiance", 3);
        for (std::size_t e = 0; e < all.size(); ++e)
            for (int k = 0; k < 3; ++k) h.values.push_back(irradiance[e][k]);
    }
    VtuCellArray& surface = cellArray(grid, "surface", 1, true);
    VtuCellArray& side = cellArray(grid, "side", 1, true);
    VtuCellArray& patch = cellArray(grid, "patch", 1, true);
    VtuCellArray& area = cellArray(grid, "area");
    for (const Element& element : all) {
        points.triangle(element.p);
        const MeshSurface& s = mesh.surfaces[mesh.patches[element.patch].surface];
        surface.values.push_back(mesh.patches[element.patch].surface);
        side.values.push_back(s.back ? 1 : 0);
        patch.values.push_back(element.patch);
        area.values.push_back(element.area);
    }
    return grid;
}

VtuGrid exchangeGrid(const PreparedScene& scene, const ExchangeEstimate& e) {
    const Mesh& mesh = scene.mesh();
    if (e.table.size() != mesh.surfaces.size()) throw std::logic_error("exchange grid: surfaces do not match");
    VtuGrid grid;
    grid.comments.push_back(
        "radiative exchange: one cell per patch; net_heat is the cell's part (net_flux x area), W; fluxes W/m^2");
    surfaceComments(grid, mesh);
    PointTable points(grid, scene.scene().origin);
    const ExchangeSolution& s = e.solution;
    VtuCellArray* arrays[10];
    const char* names[] = {"surface", "side",      "area",       "emissivity", "temperature", "net_flux",
                           "net_heat", "radiosity", "irradiance", "to_space"};
    for (int k = 0; k < 10; ++k) arrays[k] = &cellArray(grid, names[k], 1, k < 2);
    for (const Patch& patch : mesh.patches) {
        points.triangle(patch.p);
        const std::size_t i = patch.surface;
        const double values[] = {static_cast<double>(i),
                                 mesh.surfaces[i].back ? 1.0 : 0.0,
                                 patch.area,
                                 e.problem.conditions[i].emissivity,
                                 s.temperature[i],
                                 s.netFlux[i],
                                 s.netFlux[i] * patch.area,
                                 s.radiosity[i],
                                 s.irradiance[i],
                                 e.toSpace[i]};
        for (int k = 0; k < 10; ++k) arrays[k]->values.push_back(values[k]);
    }
    return grid;
}

}  // namespace rad
