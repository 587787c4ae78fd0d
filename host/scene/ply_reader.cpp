// PLY (scene/mesh_readers.h): the header's elements and properties, then each element's rows in
// ASCII or binary of either byte order. The vertex positions (and normals, colours and texture
// coordinates), the faces' corner lists (and MeshLab's per-corner texcoord) and the texture a
// "comment TextureFile" names are kept; every other element and property is read past.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <tuple>

#include <glm/geometric.hpp>

#include "scene/image_decode.h"
#include "scene/material_model.h"
#include "scene/mesh_readers.h"
#include "util/error.h"

namespace rad {
namespace {

// The shortest text that reads back as v: what the file most likely says.
std::string number(double v) {
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::strtod(text, nullptr) == v) break;
    }
    return text;
}

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parseType(const std::string& name, Type& type) {
    static const std::pair<const char*, Type> kNames[] = {
        {"char", Type::Int8},     {"int8", Type::Int8},     {"uchar", Type::UInt8},   {"uint8", Type::UInt8},
        {"short", Type::Int16},   {"int16", Type::Int16},   {"ushort", Type::UInt16}, {"uint16", Type::UInt16},
        {"int", Type::Int32},     {"int32", Type::Int32},   {"uint", Type::UInt32},   {"uint32", Type::UInt32},
        {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
    for (const auto& [text, value] : kNames)
        if (name == text) {
            type = value;
            return true;
        }
    return false;
}

std::size_t sizeOf(Type type) {
    switch (type) {
        case Type::Int8: case Type::UInt8: return 1;
        case Type::Int16: case Type::UInt16: return 2;
        case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
        case Type::Float64: return 8;
    }
    return 0;
}

struct Property {
    std::string name;
    Type type = Type::Float32;
    bool list = false;
    Type countType = Type::UInt8;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

class PlyFile {
public:
    PlyFile(std::string bytes, const std::string& path) : bytes_(std::move(bytes)), path_(path) {}

    FileMesh read() {
        readHeader();
        FileMesh out;
        out.warnings = std::move(headerWarnings_);
        out.surfaces.emplace_back();
        FileSurface& surface = out.surfaces.back();
        surface.name = std::filesystem::path(path_).stem().string();
        bool sawVertices = false;
        for (const Element& element : elements_) {
            if (element.name == "vertex") {
                if (sawVertices) fail("has two vertex elements");
                readVertices(element, surface);
                sawVertices = true;
            } else if (element.name == "face") {
                if (!sawVertices) fail("the face element comes before the vertex element");
                readFaces(element, surface, out.skippedElements);
            } else {
                for (std::uint64_t r = 0; r < element.count; ++r)
                    for (const Property& p : element.properties) readProperty(p, element);
            }
        }
        if (!sawVertices) fail("has no vertex element");
        out.warnings.insert(out.warnings.end(), faceWarnings_.begin(), faceWarnings_.end());
        if (!textureFile_.empty()) readTexture(out);
        if (format_ == Format::Ascii) {  // values the header does not describe: it misreads the data
            while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_]))) ++at_;
            if (at_ < bytes_.size())
                fail("has values after its last element that the header does not describe (at byte " +
                     std::to_string(at_) + ")");
        }
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw FileError(path_, problem); }

    // The image "comment TextureFile" names (beside the PLY), as the base colour texture of a
    // white material of every face, where the mesh has texture coordinates; a warning where it
    // cannot be read or they are missing.
    void readTexture(FileMesh& out) {
        FileSurface& surface = out.surfaces.back();
        if (badTexcoords_ > 0)
            out.warnings.push_back(std::to_string(badTexcoords_) +
                                   " face(s) whose texcoord list is not two numbers a corner read texel (0, 0)");
        if (textureFiles_ > 1 || texnumber_)
            out.warnings.push_back("names " + std::to_string(textureFiles_) + " TextureFile(s)" +
                                   (texnumber_ ? " and says per face which (texnumber)" : "") +
                                   ": every face takes the first, '" + textureFile_ + "'");
        if (surface.texCoords.empty()) {
            out.warnings.push_back("TextureFile '" + textureFile_ +
                                   "' is not read: the mesh has no texture coordinates");
            return;
        }
        const std::string where = imagePath(std::filesystem::path(path_).parent_path().string(), textureFile_);
        TextureImage image;
        std::string why;
        long long budget = kMostImageTexels;
        if (!readImageFile(where, &budget, image, why)) {
            out.warnings.push_back("TextureFile '" + where + "' " + why + "; the mesh is white");
            return;
        }
        out.extraFiles.push_back(where);  // part of the scene (checkpoints' fingerprint)
        Material m;
        m.name = surface.name;
        m.metallic = 0.0f;
        m.roughness = 1.0f;
        m.reflectance = plainReflectance(m);
        m.baseColorTexture.image = 0;
        out.images.push_back(std::move(image));
        out.materials.push_back(m);
        surface.materials.assign(surface.triangles.size(), 0);
        if (!surface.colors.empty()) {  // a scan's colours and its texture are two records of one albedo
            surface.colors.clear();
            out.warnings.push_back("its vertex colours are not read: the texture gives the colour");
        }
    }

    // A header word that begins, in any case, as one of the keywords that say how the data is
    // laid out ("Element", "elemnt", "element2", "PROPERTY", "endheader"): passing over such a
    // line would misread the data. Anything else ("Created", "COMMENT", "PLY file") is prose.
    static bool looksLikeKeyword(const std::string& word) {
        std::string lower;
        for (unsigned char c : word) lower.push_back(static_cast<char>(std::tolower(c)));
        for (const char* stem : {"elem", "prop", "form", "end"})
            if (lower.rfind(stem, 0) == 0) return true;
        return false;
    }
    std::vector<std::string> headerWarnings_;
    std::vector<std::string> faceWarnings_;

    std::string headerLine() {
        const std::size_t end = bytes_.find('\n', at_);
        if (end == std::string::npos) fail("the header has no end_header line");
        std::string line = bytes_.substr(at_, end - at_);
        at_ = end + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return line;
    }

    void readHeader() {
        if (headerLine() != "ply") fail("is not PLY: it does not begin with the line 'ply'");
        bool formatGiven = false;
        std::string passedOver;  // the line just passed over as not PLY, if the last was one
        for (;;) {
            std::istringstream line(headerLine());
            std::string word;
            line >> word;
            if (word == "end_header") break;
            if (word == "comment") {  // MeshLab names the mesh's texture: "comment TextureFile name.png"
                std::string key, file;
                line >> key;
                std::getline(line >> std::ws, file);
                while (!file.empty() && std::isspace(static_cast<unsigned char>(file.back()))) file.pop_back();
                if (key == "TextureFile" && !file.empty() && ++textureFiles_ == 1) textureFile_ = file;
                continue;
            }
            if (word.empty() || word == "obj_info") continue;
            if (word == "format") {
                std::string name, version;
                line >> name >> version;
                if (name == "ascii") format_ = Format::Ascii;
                else if (name == "binary_little_endian") format_ = Format::BinaryLittle;
                else if (name == "binary_big_endian") format_ = Format::BinaryBig;
                else fail("unknown format '" + name + "' (ascii, binary_little_endian or binary_big_endian)");
                formatGiven = true;
            } else if (word == "element") {
                Element element;
                std::string count;
                line >> element.name >> count;
                char* end = nullptr;
                const double n = std::strtod(count.c_str(), &end);
                if (count.empty() || *end || !(n >= 0.0) || n > 4294967295.0 || n != std::floor(n))
                    fail("element '" + element.name + "' has the count '" + count + "', not a whole number below 2^32");
                element.count = static_cast<std::uint64_t>(n);
                elements_.push_back(element);
            } else if (word == "property") {
                if (elements_.empty()) fail("a property comes before any element");
                if (!passedOver.empty())
                    fail("a property comes after the header line '" + passedOver.substr(0, 80) +
                         "', which is not PLY, with no element between: is that line a misspelt element?");
                Property p;
                std::string type;
                line >> type;
                if (type == "list") {
                    std::string countType, itemType;
                    line >> countType >> itemType >> p.name;
                    p.list = true;
                    if (!parseType(countType, p.countType) || !parseType(itemType, p.type))
                        fail("property list '" + p.name + "' has an unknown type");
                } else {
                    line >> p.name;
                    if (!parseType(type, p.type)) fail("property '" + p.name + "' has the unknown type '" + type + "'");
                }
                elements_.back().properties.push_back(p);
            } else if (looksLikeKeyword(word)) {
                fail("unknown header line beginning '" + word + "'");
            } else {
                // Not a keyword at all: text some exporters (Blender 2.4x) wrote without the word
                // `comment`. The elements and properties say what the data holds; this line
                // cannot, so it is passed over, and said. A property right after it is refused
                // below: the line may then have been an element.
                headerWarnings_.push_back("the header line '" + line.str().substr(0, 80) +
                                          "' is not PLY (a comment without 'comment'?); passed over");
                passedOver = line.str();
                continue;
            }
            passedOver.clear();
        }
        if (!formatGiven) fail("the header gives no format line");
    }

    // One value of `type`, as a double (ASCII: a token; binary: bytes in the file's order).
    double value(Type type, const Element& element) {
        if (format_ == Format::Ascii) {
            while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_]))) ++at_;
            const std::size_t start = at_;
            while (at_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[at_]))) ++at_;
            const std::string token = bytes_.substr(start, at_ - start);
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            if (token.empty() || *end) fail("element '" + element.name + "': expected a number, found '" +
                                            (token.empty() ? "the end of the file" : token) + "'");
            return v;
        }
        const std::size_t size = sizeOf(type);
        if (bytes_.size() - at_ < size) fail("ends inside element '" + element.name + "' (the header promises more)");
        unsigned char b[8];
        std::memcpy(b, bytes_.data() + at_, size);
        at_ += size;
        if (format_ == Format::BinaryBig)
            for (std::size_t k = 0; k < size / 2; ++k) std::swap(b[k], b[size - 1 - k]);
        switch (type) {
            case Type::Int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
            case Type::UInt8: return b[0];
            case Type::Int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
            case Type::UInt16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
            case Type::Int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
            case Type::UInt32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
            case Type::Float32: { float v; std::memcpy(&v, b, 4); return v; }
            case Type::Float64: { double v; std::memcpy(&v, b, 8); return v; }
        }
        return 0.0;
    }

    // A list's length: a whole number; a face's at most 2^16 corners (the list is held at once).
    std::size_t listLength(const Property& p, const Element& element, double largest = 4294967295.0) {
        const double n = value(p.countType, element);
        if (!(n >= 0.0) || n > largest || n != std::floor(n))
            fail("element '" + element.name + "': list '" + p.name + "' has the length " + number(n) + ", not a whole number from 0 to " + number(largest));
        return static_cast<std::size_t>(n);
    }

    void readProperty(const Property& p, const Element& element) {
        if (!p.list) {
            value(p.type, element);
            return;
        }
        const std::size_t n = listLength(p, element);
        for (std::size_t k = 0; k < n; ++k) value(p.type, element);
    }

    // The columns of an element's colour (red, green, blue, or diffuse_red ...), or -1s.
    static std::array<int, 3> colourColumns(const Element& element) {
        std::array<int, 3> colour = {-1, -1, -1};
        const char* channels[3] = {"red", "green", "blue"};
        for (std::size_t k = 0; k < element.properties.size(); ++k)
            for (int c = 0; c < 3; ++c) {
                const std::string& name = element.properties[k].name;
                if (!element.properties[k].list && (name == channels[c] || name == std::string("diffuse_") + channels[c]))
                    colour[static_cast<std::size_t>(c)] = static_cast<int>(k);
            }
        return colour;
    }

    // A colour read from `row` (integers over their type's largest value, floats as they are;
    // sRGB, as scanners and MeshLab write them), made linear.
    static glm::dvec3 linearColour(const Element& element, const std::array<int, 3>& colour, const std::vector<double>& row) {
        glm::dvec3 c;
        for (int k = 0; k < 3; ++k) {
            const Property& p = element.properties[static_cast<std::size_t>(colour[static_cast<std::size_t>(k)])];
            const double largest = p.type == Type::UInt8     ? 255.0
                                   : p.type == Type::Int8    ? 127.0
                                   : p.type == Type::UInt16  ? 65535.0
                                   : p.type == Type::Int16   ? 32767.0
                                   : p.type == Type::UInt32  ? 4294967295.0
                                   : p.type == Type::Int32   ? 2147483647.0
                                                             : 1.0;  // floats as they are
            const double v = row[static_cast<std::size_t>(colour[static_cast<std::size_t>(k)])] / largest;
            c[k] = srgbComponentToLinear(std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 1.0);
        }
        return c;
    }

    void readVertices(const Element& element, FileSurface& surface) {
        int position[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1};
        const char* axes[3] = {"x", "y", "z"};
        const char* normals[3] = {"nx", "ny", "nz"};
        for (std::size_t k = 0; k < element.properties.size(); ++k)
            for (int a = 0; a < 3; ++a) {
                if (element.properties[k].name == axes[a] && !element.properties[k].list) position[a] = static_cast<int>(k);
                if (element.properties[k].name == normals[a] && !element.properties[k].list) normal[a] = static_cast<int>(k);
            }
        if (position[0] < 0 || position[1] < 0 || position[2] < 0) fail("the vertex element lacks x, y or z");
        const bool withNormals = normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0;
        // Vertex colours (linearColour)
        const std::array<int, 3> colour = colourColumns(element);
        const bool withColours = colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0;
        // Texture coordinates per vertex (s t, u v, or texture_u texture_v), v counted from the
        // image's bottom as OpenGL and MeshLab count it.
        int uv[2] = {-1, -1};
        for (const auto& [u, v] : {std::pair{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}})
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                if (element.properties[k].list) continue;
                if (element.properties[k].name == u) uv[0] = static_cast<int>(k);
                if (element.properties[k].name == v) uv[1] = static_cast<int>(k);
            }
        const bool withUv = uv[0] >= 0 && uv[1] >= 0;
        std::vector<double> row(element.properties.size(), 0.0);
        for (std::uint64_t r = 0; r < element.count; ++r) {
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const Property& p = element.properties[k];
                if (p.list)
                    readProperty(p, element);
                else
                    row[k] = value(p.type, element);
            }
            const glm::dvec3 point(row[static_cast<std::size_t>(position[0])], row[static_cast<std::size_t>(position[1])],
                                   row[static_cast<std::size_t>(position[2])]);
            if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
                fail("vertex " + std::to_string(r) + " (counting from 0) is not a finite point");
            surface.positions.push_back(point);
            if (withNormals) {
                const glm::dvec3 n(row[static_cast<std::size_t>(normal[0])], row[static_cast<std::size_t>(normal[1])],
                                   row[static_cast<std::size_t>(normal[2])]);
                // A scan's reconstruction leaves NaN normals at degenerate vertices: such a normal,
                // like a zero one, has no direction, and the faces around it are shaded flat.
                const bool usable = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
                                    glm::length(n) > 1e-12;
                if (!usable) ++surface.zeroNormals;
                surface.normals.push_back(usable ? n : glm::dvec3(0.0));
            }
            if (withColours) surface.colors.push_back(linearColour(element, colour, row));
            if (withUv) {
                const double u = row[static_cast<std::size_t>(uv[0])], v = row[static_cast<std::size_t>(uv[1])];
                surface.texCoords.emplace_back(std::isfinite(u) ? u : 0.0, std::isfinite(v) ? 1.0 - v : 0.0);
            }
        }
    }

    void readFaces(const Element& element, FileSurface& surface, std::size_t& skipped) {
        int corners = -1;
        for (std::size_t k = 0; k < element.properties.size(); ++k)
            if (element.properties[k].list &&
                (element.properties[k].name == "vertex_indices" || element.properties[k].name == "vertex_index"))
                corners = static_cast<int>(k);
        if (corners < 0) fail("the face element has no vertex_indices list");
        // MeshLab's texture coordinates per corner ("texcoord": u v for each corner, in order): a
        // vertex is made for each (vertex, u, v) the faces use.
        int wedges = -1;
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
            if (element.properties[k].list && element.properties[k].name == "texcoord") wedges = static_cast<int>(k);
            if (element.properties[k].name == "texnumber") texnumber_ = true;
        }
        // Face colours (as trimesh, Open3D and segmentation tools write them): each face's corners
        // take its colour, a vertex made for each (vertex, colour) the faces use; over a vertex
        // colour the file also gives.
        const std::array<int, 3> faceColour = colourColumns(element);
        const bool withFaceColours = faceColour[0] >= 0 && faceColour[1] >= 0 && faceColour[2] >= 0;
        if (withFaceColours && !surface.colors.empty())
            faceWarnings_.push_back("the faces' colours are taken over the vertices' colours");
        std::map<std::tuple<std::uint32_t, double, double>, std::uint32_t> split;
        std::map<std::tuple<std::uint32_t, double, double, double>, std::uint32_t> coloured;
        std::vector<bool> claimed;  // whether a vertex has taken a face's colour
        const std::size_t original = surface.positions.size();
        std::vector<std::uint32_t> polygon;
        std::vector<double> corner;
        std::vector<double> row(element.properties.size(), 0.0);
        for (std::uint64_t r = 0; r < element.count; ++r) {
            corner.clear();
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const Property& p = element.properties[k];
                if (static_cast<int>(k) == wedges) {
                    corner.resize(listLength(p, element, 131072.0));
                    for (double& c : corner) c = value(p.type, element);
                    continue;
                }
                if (static_cast<int>(k) != corners) {
                    if (p.list) readProperty(p, element);
                    else row[k] = value(p.type, element);
                    continue;
                }
                polygon.resize(listLength(p, element, 65536.0));
                for (std::uint32_t& index : polygon) {
                    const double v = value(p.type, element);
                    if (!(v >= 0.0) || v >= static_cast<double>(original) || v != std::floor(v))
                        fail("face " + std::to_string(r) + " (counting from 0) names vertex " + number(v) + " of " +
                             std::to_string(original));
                    index = static_cast<std::uint32_t>(v);
                }
            }
            if (wedges >= 0 && corner.size() != 2 * polygon.size()) ++badTexcoords_;
            if (wedges >= 0 && corner.size() == 2 * polygon.size()) {
                if (surface.texCoords.empty()) surface.texCoords.assign(original, glm::dvec2(0.0));
                for (std::size_t c = 0; c < polygon.size(); ++c) {
                    const double u = std::isfinite(corner[2 * c]) ? corner[2 * c] : 0.0;
                    const double v = std::isfinite(corner[2 * c + 1]) ? 1.0 - corner[2 * c + 1] : 0.0;
                    const auto next = static_cast<std::uint32_t>(surface.positions.size());
                    const auto [at, fresh] = split.emplace(std::make_tuple(polygon[c], u, v), next);
                    if (fresh) {
                        const std::uint32_t from = polygon[c];
                        surface.positions.push_back(surface.positions[from]);
                        if (!surface.normals.empty()) surface.normals.push_back(surface.normals[from]);
                        if (!surface.colors.empty()) surface.colors.push_back(surface.colors[from]);
                        surface.texCoords.emplace_back(u, v);
                    }
                    polygon[c] = at->second;
                }
            }
            if (withFaceColours && polygon.size() >= 3) {
                const glm::dvec3 c = linearColour(element, faceColour, row);
                if (surface.colors.size() < surface.positions.size())
                    surface.colors.resize(surface.positions.size(), glm::dvec3(1.0));  // white till then
                claimed.resize(surface.positions.size(), false);
                for (std::uint32_t& v : polygon) {
                    // a vertex's first face colour is its own; another face's makes a copy
                    const std::uint32_t target =
                        claimed[v] ? static_cast<std::uint32_t>(surface.positions.size()) : v;
                    const auto [at, fresh] = coloured.emplace(std::make_tuple(v, c.x, c.y, c.z), target);
                    if (fresh && target == v) {
                        claimed[v] = true;
                        surface.colors[v] = c;
                    } else if (fresh) {
                        surface.positions.push_back(surface.positions[v]);
                        if (!surface.normals.empty()) surface.normals.push_back(surface.normals[v]);
                        if (!surface.texCoords.empty()) surface.texCoords.push_back(surface.texCoords[v]);
                        surface.colors.push_back(c);
                        claimed.push_back(true);
                    }
                    v = at->second;
                }
            }
            if (polygon.size() < 3) ++skipped;
            appendPolygon(polygon, -1, surface);  // readTexture gives them its material
        }
    }

    std::string textureFile_;  // the first "comment TextureFile", where the header has one
    int textureFiles_ = 0;     // how many it names
    bool texnumber_ = false;   // whether faces say which (MeshLab's texnumber), which is not read
    std::size_t badTexcoords_ = 0;  // faces whose texcoord list is not two numbers a corner
    std::string bytes_;
    const std::string& path_;
    std::size_t at_ = 0;
    Format format_ = Format::Ascii;
    std::vector<Element> elements_;
};

}  // namespace

FileMesh readPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot be opened for reading");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return PlyFile(bytes.str(), path).read();
}

}  // namespace rad
