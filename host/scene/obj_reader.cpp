// Wavefront OBJ (scene/mesh_readers.h). tinyobjloader is built here with double precision, so a
// coordinate written with more digits than a float holds rounds once, to the nearest float.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <tiny_obj_loader.h>

#include "scene/image_decode.h"
#include "scene/material_model.h"
#include "scene/mesh_readers.h"
#include "util/error.h"

namespace rad {
namespace {

std::string lines(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (char& c : text)
        if (c == '\n') c = ';';
    return text;
}

// The image a map statement names (relative to the OBJ's folder, as MTL files are), as a
// texture of the material: -s and -o (scale and offset of u and v) become its transform, in
// glTF's texture coordinates (v from the top: FileSurface::texCoords), -clamp its wrapping. An
// image that cannot be read leaves the factor alone, with a warning.
TextureRef mapTexture(const std::string& file, const tinyobj::texture_option_t& options, const std::string& folder,
                      const std::string& what, FileMesh& out, long long& budget) {
    TextureRef ref;
    if (file.empty()) return ref;
    const std::string where = imagePath(folder, file);
    std::string why;
    const auto known =
        std::find_if(out.images.begin(), out.images.end(), [&](const TextureImage& i) { return i.name == where; });
    TextureImage image;
    if (known != out.images.end()) {  // materials that share an atlas share its texels
        ref.image = static_cast<int>(known - out.images.begin());
    } else if (readImageFile(where, &budget, image, why)) {
        ref.image = static_cast<int>(out.images.size());
        out.images.push_back(std::move(image));
        out.extraFiles.push_back(where);  // part of the scene (checkpoints' fingerprint)
    } else {
        out.warnings.push_back(what + ": '" + where + "' " + why + "; its factor alone is used");
        return ref;
    }
    if (options.clamp) ref.wrapS = ref.wrapT = TextureRef::Wrap::ClampToEdge;
    const float su = static_cast<float>(options.scale[0]), sv = static_cast<float>(options.scale[1]);
    const float ou = static_cast<float>(options.origin_offset[0]), ov = static_cast<float>(options.origin_offset[1]);
    // OBJ's (u, v) -> (su u + ou, sv v + ov), with v counted from the bottom: in glTF's v = 1 - v_obj,
    // v -> sv v + (1 - sv - ov).
    ref.transform = glm::mat3(glm::vec3(su, 0.0f, 0.0f), glm::vec3(0.0f, sv, 0.0f), glm::vec3(ou, 1.0f - sv - ov, 1.0f));
    return ref;
}

// MTL's dissolve, d (or Tr, 1 - d) and map_d, as the cut-outs exporters mean by them (leaves,
// fences, grilles): glTF's alpha MASK at 0.5, light passing where d times map_d is below it.
// map_d's value is its alpha where it has one, else its red (a grey image); it becomes the alpha
// of the base colour texture (a white one where the material has none), which must then have
// its size. Partial transparency is read as the mask too, with a warning, as glTF's BLEND is.
void readCutOut(const tinyobj::material_t& source, const std::string& folder, const std::string& what, Material& m,
                FileMesh& out, long long& budget) {
    const float dissolve =
        std::isfinite(source.dissolve) ? std::clamp(static_cast<float>(source.dissolve), 0.0f, 1.0f) : 1.0f;
    const TextureRef mask = mapTexture(source.alpha_texname, source.alpha_texopt, folder, what + " (map_d)", out, budget);
    if (mask.present()) {
        const TextureImage cut = out.images[static_cast<std::size_t>(mask.image)];
        bool withAlpha = false;
        for (std::size_t i = 3; i < cut.rgba.size() && !withAlpha; i += 4) withAlpha = cut.rgba[i] < 255;
        // The cut texture is an image of its own (others may share the base colour's or the
        // mask's), made once for each pair of them.
        const std::string cutName =
            (m.baseColorTexture.present() ? out.images[static_cast<std::size_t>(m.baseColorTexture.image)].name
                                          : std::string("white")) +
            " cut by " + cut.name;
        const auto made = std::find_if(out.images.begin(), out.images.end(),
                                       [&](const TextureImage& i) { return i.name == cutName; });
        const bool white = !m.baseColorTexture.present();
        if (white) m.baseColorTexture = mask;  // white, cut by the mask
        TextureImage base;
        if (made == out.images.end()) {
            base = out.images[static_cast<std::size_t>(m.baseColorTexture.image)];
            budget -= static_cast<long long>(base.width) * base.height;  // the cut image is one more
            for (std::size_t i = 0; white && i < base.rgba.size(); i += 4)
                base.rgba[i] = base.rgba[i + 1] = base.rgba[i + 2] = 255;
        }
        if (made != out.images.end()) {
            m.baseColorTexture.image = static_cast<int>(made - out.images.begin());
            m.alphaMode = Material::AlphaMode::Mask;
        } else if (budget < 0) {
            out.warnings.push_back(what + ": map_d is not read: the file's images hold more texels than the program reads");
            if (white) m.baseColorTexture = TextureRef();
        } else if (base.width != cut.width || base.height != cut.height) {
            out.warnings.push_back(what + ": map_d is " + std::to_string(cut.width) + " x " + std::to_string(cut.height) +
                                   " texels and map_Kd " + std::to_string(base.width) + " x " +
                                   std::to_string(base.height) + ": map_d is not read");
        } else {
            for (std::size_t i = 0; i < base.rgba.size(); i += 4) base.rgba[i + 3] = cut.rgba[withAlpha ? i + 3 : i];
            base.name = cutName;
            m.baseColorTexture.image = static_cast<int>(out.images.size());
            out.images.push_back(std::move(base));
            m.alphaMode = Material::AlphaMode::Mask;
        }
    }
    if (dissolve < 1.0f) {
        m.alphaMode = Material::AlphaMode::Mask;
        out.warnings.push_back(what + ": d " + std::to_string(dissolve) +
                               " (partial transparency) is read as a cut-out: light passes where d" +
                               (mask.present() ? " times map_d" : "") + " is below 0.5");
    }
    m.alpha = dissolve;
    m.alphaCutoff = 0.5f;
}

// The keys an MTL material gives (Ks, Ns, Pr, ...): tinyobjloader's values do not say which
// were left out, and a key left out means something else than its default.
using MaterialKeys = std::set<std::string>;

// The specular part of an MTL material, as Blender's OBJ importer reads it, so that a file drawn
// here and the same file imported into Blender show the same surface:
// - roughness: Pr (the PBR extension), else 1 - sqrt(Ns / 1000) (Ns, the Phong exponent, in 0 -
//   1000; Blender's exporter writes (1 - roughness)^2 x 1000), else 1;
// - metallic: Pm, else the mean of Ka where illum is 3 (Blender's exporter writes metallic there),
//   else 0;
// - a non-metal's specular layer: Ks's mean is Blender's "specular IOR level", so F0 is that
//   times 2 times the F0 of the index of refraction Ni (0.04 at 1.5; Ni below 1 or absent: 1.5):
//   glTF's default layer at Ks 0.5. Without Ks, none, unless the material gives Pr or Pm (a
//   material written for a metallic-roughness model): glTF's default layer then.
void readSpecular(const tinyobj::material_t& source, const MaterialKeys& keys, const std::string& what,
                  Material& m, std::vector<std::string>& warnings) {
    auto given = [&](const char* key) { return keys.count(key) > 0; };
    auto unit = [&](double value, const char* key) {
        if (!std::isfinite(value) || value < 0.0 || value > 1.0) {
            warnings.push_back(what + ": " + key + " " + std::to_string(value) + " outside [0, 1] is clamped");
            return std::isfinite(value) ? static_cast<float>(std::clamp(value, 0.0, 1.0)) : 0.0f;
        }
        return static_cast<float>(value);
    };
    const bool pbr = given("Pr") || given("Pm");
    if (given("Pr")) m.roughness = unit(source.roughness, "Pr");
    else if (given("Ns") && std::isfinite(source.shininess))
        m.roughness = 1.0f - static_cast<float>(std::sqrt(std::clamp(source.shininess, 0.0, 1000.0) / 1000.0));
    if (given("Pm")) m.metallic = unit(source.metallic, "Pm");
    else if (source.illum == 3 && given("Ka"))
        m.metallic = unit((source.ambient[0] + source.ambient[1] + source.ambient[2]) / 3.0, "Ka (illum 3: metallic)");
    // Ni 1 (some exporters' "none"): no reflection at all, as in Blender, rather than glTF's
    // Schlick sheen toward grazing
    const bool unreflecting = given("Ni") && std::isfinite(source.ior) && source.ior >= 1.0 && source.ior <= 1.0001;
    if (given("Ni") && std::isfinite(source.ior) && source.ior > 1.0001 && source.ior <= 10.0)
        m.ior = static_cast<float>(source.ior);
    if (given("Ks")) {
        const double level = (source.specular[0] + source.specular[1] + source.specular[2]) / 3.0;
        const float clamped = std::isfinite(level) ? static_cast<float>(std::clamp(level, 0.0, 16.0)) : 0.0f;
        m.specular = clamped > 0.0f ? 1.0f : 0.0f;
        m.specularColor = glm::vec3(2.0f * clamped);
    } else if (pbr) {
        m.specular = 1.0f;  // glTF's default layer
    }
    if (unreflecting) m.specular = 0.0f;
}

// An OBJ's normal map, as Blender's OBJ importer reads map_Bump (Blender's exporter writes a
// normal map there, its strength as -bm): a tangent-space normal map (glTF's normalTexture, read
// linear, in the vt coordinates), -bm its scale; the PBR extension's `norm` the same. An image
// that is not one (a grey height map, as older tools mean by bump: its texels' (2 rgb - 1) are not
// unit vectors leaning toward +z) is not read, with a warning: as a normal map it would turn the
// surface on its side.
void readNormalMap(const tinyobj::material_t& source, const std::string& folder, const std::string& what,
                   Material& m, FileMesh& out, long long& budget) {
    const bool norm = !source.normal_texname.empty();
    const std::string key = norm ? "norm" : "map_Bump";
    const tinyobj::texture_option_t& options = norm ? source.normal_texopt : source.bump_texopt;
    TextureRef ref = mapTexture(norm ? source.normal_texname : source.bump_texname, options, folder,
                                what + " (" + key + ")", out, budget);
    if (!ref.present()) return;
    const TextureImage& image = out.images[static_cast<std::size_t>(ref.image)];
    double lean = 0.0, length = 0.0;
    std::size_t grey = 0;  // texels with r = g = b (to a level), which a height map's all are
    const std::size_t texels = image.rgba.size() / 4;
    for (std::size_t i = 0; i < texels; ++i) {
        const std::uint8_t* t = &image.rgba[4 * i];
        const glm::dvec3 n = glm::dvec3(t[0], t[1], t[2]) / 127.5 - 1.0;
        lean += n.z;
        length += glm::dot(n, n);
        if (std::abs(t[0] - t[1]) <= 1 && std::abs(t[1] - t[2]) <= 1) ++grey;
    }
    const double count = static_cast<double>(texels);
    if (texels == 0 || !(lean / count > 0.4 && std::fabs(length / count - 1.0) < 0.35) || grey > texels / 2) {
        out.warnings.push_back(what + ": " + key + " '" + image.name +
                               "' is not a normal map (a height map?): it is not read");
        return;
    }
    double scale = options.bump_multiplier;
    if (!(scale >= 0.0 && scale <= 100.0)) {
        const double clamped = std::isfinite(scale) ? std::clamp(scale, 0.0, 100.0) : 1.0;
        out.warnings.push_back(what + ": " + key + " -bm " + std::to_string(scale) + " is read as " + std::to_string(clamped));
        scale = clamped;
    }
    ref.linear = true;
    m.normalTexture = ref;
    m.normalScale = static_cast<float>(scale);
}

// Roughness and metal maps, as Blender's OBJ importer reads them: map_Pr (or map_Ns, where
// Blender's exporter writes a roughness texture) gives the roughness and map_Pm (or map_refl)
// the metallic, each texel's grey in place of the factor; put together as glTF's
// metallicRoughnessTexture (green roughness, blue metal; 1 in the channel of a map not given,
// which leaves that factor), in the first map's coordinates and size (the second's texels taken
// at the nearest place).
void readMetalRoughness(const tinyobj::material_t& source, const std::string& folder, const std::string& what,
                        Material& m, FileMesh& out, long long& budget) {
    std::string metalFile = source.metallic_texname, metalKey = "map_Pm";
    tinyobj::texture_option_t metalOptions = source.metallic_texopt;
    if (metalFile.empty()) {  // tinyobjloader keeps map_refl as an unknown key, its options and file unparsed
        const auto refl = source.unknown_parameter.find("map_refl");
        if (refl != source.unknown_parameter.end()) {
            tinyobj::ParseTextureNameAndOption(&metalFile, &metalOptions, refl->second.c_str());
            metalKey = "map_refl";
        }
    }
    const bool pr = !source.roughness_texname.empty();
    const std::string roughKey = pr ? "map_Pr" : "map_Ns";
    const TextureRef rough = mapTexture(pr ? source.roughness_texname : source.specular_highlight_texname,
                                        pr ? source.roughness_texopt : source.specular_highlight_texopt, folder,
                                        what + " (" + roughKey + ")", out, budget);
    const TextureRef metal = mapTexture(metalFile, metalOptions, folder, what + " (" + metalKey + ")", out, budget);
    if (!rough.present() && !metal.present()) return;
    const TextureRef first = rough.present() ? rough : metal;
    // (a name no file has: an image's name is its path)
    const std::string name = "<metal " + (metal.present() ? out.images[static_cast<std::size_t>(metal.image)].name : "") +
                             ", roughness " + (rough.present() ? out.images[static_cast<std::size_t>(rough.image)].name : "") + ">";
    const auto made = std::find_if(out.images.begin(), out.images.end(), [&](const TextureImage& i) { return i.name == name; });
    TextureRef ref = first;
    ref.linear = true;
    if (made != out.images.end()) {
        ref.image = static_cast<int>(made - out.images.begin());
    } else {
        const TextureImage& shape = out.images[static_cast<std::size_t>(first.image)];
        budget -= static_cast<long long>(shape.width) * shape.height;
        if (budget < 0) {
            out.warnings.push_back(what + ": " + roughKey + " and " + metalKey +
                                   " are not read: the file's images hold more texels than the program reads");
            return;
        }
        TextureImage combined;
        combined.name = name;
        combined.width = shape.width;
        combined.height = shape.height;
        combined.rgba.assign(shape.rgba.size(), 255);
        // grey of texel (x, y) of `ref`'s image, taken at the nearest place to (x, y) of the first's
        auto grey = [&](const TextureRef& from, int x, int y) {
            const TextureImage& i = out.images[static_cast<std::size_t>(from.image)];
            const auto u = static_cast<std::size_t>(std::min<long long>(i.width - 1, static_cast<long long>(x) * i.width / shape.width));
            const auto v = static_cast<std::size_t>(std::min<long long>(i.height - 1, static_cast<long long>(y) * i.height / shape.height));
            const std::uint8_t* t = &i.rgba[4 * (v * static_cast<std::size_t>(i.width) + u)];
            return static_cast<std::uint8_t>((t[0] + t[1] + t[2] + 1) / 3);
        };
        for (int y = 0; y < shape.height; ++y)
            for (int x = 0; x < shape.width; ++x) {
                std::uint8_t* texel = &combined.rgba[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(shape.width) + static_cast<std::size_t>(x))];
                if (rough.present()) texel[1] = grey(rough, x, y);
                if (metal.present()) texel[2] = grey(metal, x, y);
            }
        ref.image = static_cast<int>(out.images.size());
        out.images.push_back(std::move(combined));
    }
    if (rough.present() && metal.present() && rough.transform != metal.transform)
        out.warnings.push_back(what + ": " + roughKey + " and " + metalKey + " are placed differently (-s, -o); both are read in " + roughKey + "'s place");
    if (rough.present()) m.roughness = 1.0f;
    if (metal.present()) m.metallic = 1.0f;
    m.metallicRoughnessTextured = true;
    m.metallicRoughnessTexture = ref;
}

Material convertMaterial(const tinyobj::material_t& source, const MaterialKeys& keys, std::size_t index,
                         const std::string& path, FileMesh& out, long long& budget) {
    std::vector<std::string>& warnings = out.warnings;
    Material m;
    m.name = source.name.empty() ? "material" + std::to_string(index) : source.name;
    const std::string what = "material '" + m.name + "'";
    for (int c = 0; c < 3; ++c) {
        m.baseColor[c] = static_cast<float>(source.diffuse[c]);
        m.emission[c] = static_cast<float>(source.emission[c]);
    }
    if (!std::isfinite(m.baseColor.x + m.baseColor.y + m.baseColor.z) ||
        !std::isfinite(m.emission.x + m.emission.y + m.emission.z))
        throw FileError(path, what + " has a colour that is not finite");
    if (glm::any(glm::lessThan(m.baseColor, glm::vec3(0.0f))) || glm::any(glm::greaterThan(m.baseColor, glm::vec3(1.0f)))) {
        warnings.push_back(what + ": Kd outside [0, 1] clamped (a reflectance above 1 creates energy)");
        m.baseColor = glm::clamp(m.baseColor, 0.0f, 1.0f);
    }
    if (glm::any(glm::lessThan(m.emission, glm::vec3(0.0f)))) throw FileError(path, what + " has a negative Ke");
    if (!(m.emission.x < 1e36f && m.emission.y < 1e36f && m.emission.z < 1e36f))
        throw FileError(path, what + " emits a radiance beyond what single precision can hold (1e36)");
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    readSpecular(source, keys, what, m, warnings);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    m.baseColorTexture = mapTexture(source.diffuse_texname, source.diffuse_texopt, folder, what + " (map_Kd)", out, budget);
    m.emissiveTexture = mapTexture(source.emissive_texname, source.emissive_texopt, folder, what + " (map_Ke)", out, budget);
    readCutOut(source, folder, what, m, out, budget);
    readNormalMap(source, folder, what, m, out, budget);
    readMetalRoughness(source, folder, what, m, out, budget);
    m.reflectance = plainReflectance(m);
    m.reflectance = radiosityReflectance(m);  // with the layer's light, where it has one
    std::string unread;
    auto notRead = [&](bool given, const char* name) {
        if (given) unread += std::string(unread.empty() ? "" : ", ") + name;
    };
    notRead(!source.specular_texname.empty(), "map_Ks");
    notRead(!source.ambient_texname.empty(), "map_Ka");
    notRead(!source.displacement_texname.empty(), "disp");
    notRead(!source.reflection_texname.empty(), "refl");
    notRead(!source.normal_texname.empty() && !source.bump_texname.empty(), "map_Bump (norm is)");
    notRead(!source.roughness_texname.empty() && !source.specular_highlight_texname.empty(), "map_Ns (map_Pr is)");
    notRead(!source.metallic_texname.empty() && source.unknown_parameter.count("map_refl") > 0, "map_refl (map_Pm is)");
    if (!unread.empty()) warnings.push_back(what + ": " + unread + " not read");
    return m;
}

// tinyobjloader reads a coordinate it cannot parse ("nan", "1,5", "abc") as 0. Every v and vn
// line is checked here first: three numbers (v may add a weight or a colour), each finite, as
// strtod reads them. Also gives the MTL files the OBJ names, which belong to the scene too.
// The file's text, as the OBJ reader takes it: ASCII or UTF-8, any UTF-8 byte-order mark removed
// (Windows editors write one, and it would hide the first line's keyword).
std::string objText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot be opened for reading");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    // OBJ is ASCII (or UTF-8) text; UTF-16 would otherwise read as "no triangles".
    if (text.rfind("\xFE\xFF", 0) == 0 || text.rfind("\xFF\xFE", 0) == 0)
        throw FileError(path, "is UTF-16 text; OBJ files are read as ASCII or UTF-8: save it as UTF-8");
    if (text.find('\0') != std::string::npos)
        throw FileError(path, "holds NUL bytes, so it is not OBJ text (UTF-16 without a byte-order mark, or binary)");
    return text;
}

// tinyobjloader's reading of the MTL files an OBJ names (beside it), with a UTF-8 byte-order mark
// passed over as in the OBJ itself: it would hide the first material's name.
class MaterialFiles : public tinyobj::MaterialReader {
public:
    explicit MaterialFiles(std::string folder) : folder_(std::move(folder)) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning, std::string* error) override {
        std::ifstream in(folder_.empty() ? std::filesystem::path(name) : std::filesystem::path(folder_) / name,
                         std::ios::binary);
        if (!in) {
            if (warning) *warning += "Material file [ " + name + " ] not found in a path : " + folder_ + "\n";
            return false;
        }
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
        std::istringstream stream(text);
        tinyobj::LoadMtl(names, materials, &stream, warning, error);
        const std::vector<NamedKeys> listed = listKeys(text);
        listed_.insert(listed_.end(), listed.begin(), listed.end());
        return true;
    }

    // The keys of each of tinyobjloader's materials, by their order and names; an empty set where
    // the two readings of the files do not agree on which material comes at that place.
    std::vector<MaterialKeys> keys(const std::vector<tinyobj::material_t>& materials) const {
        std::vector<MaterialKeys> out(materials.size());
        for (std::size_t k = 0; k < materials.size() && k < listed_.size(); ++k)
            if (listed_[k].name == materials[k].name) out[k] = listed_[k].keys;
        return out;
    }

private:
    struct NamedKeys {
        std::string name;
        MaterialKeys keys;
    };

    // The keys each named material of an MTL text gives, in order, reading the text as
    // tinyobjloader does: lines end at \n, \r\n or \r; a material starts at a line "newmtl"
    // followed by a space or tab, its name the rest of the line (trailing blanks trimmed), and a
    // material without a name is dropped (its keys too).
    static std::vector<NamedKeys> listKeys(const std::string& text) {
        std::vector<NamedKeys> out;
        bool named = false;
        std::size_t at = 0;
        while (at < text.size()) {
            std::size_t end = text.find_first_of("\r\n", at);
            if (end == std::string::npos) end = text.size();
            std::string line = text.substr(at, end - at);
            at = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
            line.erase(line.find_last_not_of(" \t") + 1);
            const std::size_t first = line.find_first_not_of(" \t");
            if (first == std::string::npos || line[first] == '#') continue;
            line.erase(0, first);
            if (line.compare(0, 6, "newmtl") == 0 && line.size() > 6 && (line[6] == ' ' || line[6] == '\t')) {
                const std::string name = line.substr(7);
                named = !name.empty();
                if (named) out.push_back({name, {}});
            } else if (named) {
                out.back().keys.insert(line.substr(0, line.find_first_of(" \t")));
            }
        }
        return out;
    }

    std::string folder_;
    std::vector<NamedKeys> listed_;
};

std::vector<std::string> checkNumbersAndListMaterialFiles(const std::string& path, const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> materialFiles;
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "mtllib") {
            std::string file;
            while (words >> file)
                materialFiles.push_back((std::filesystem::path(path).parent_path() / file).string());
            continue;
        }
        if (keyword != "v" && keyword != "vn") continue;
        std::string word;
        for (int k = 0; k < 3; ++k) {
            if (!(words >> word))
                throw FileError(path, "line " + std::to_string(number) + ": '" + keyword + "' has fewer than three numbers");
            char* end = nullptr;
            const double value = std::strtod(word.c_str(), &end);
            if (*end != '\0' || !std::isfinite(value))
                throw FileError(path, "line " + std::to_string(number) + ": '" + word + "' is not a finite number");
        }
    }
    return materialFiles;
}

// tinyobjloader counts a face's corners in a byte, so it cannot take a face of 256 or more
// corners (a CAD program's circle). Such a face line is written as pieces of at most 255
// corners, each starting at the corner the one before ends at, and `pieces` gets, for every face
// line in the file in order, how many faces it became (when all are one, the text is returned as
// it was).
std::string splitLongFaces(const std::string& text, std::vector<std::size_t>& pieces) {
    constexpr std::size_t kMostCorners = 255;
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    bool split = false;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        std::vector<std::string> corners;
        if (keyword == "f")
            for (std::string word; words >> word;) corners.push_back(word);
        // tinyobjloader drops a face of fewer than three corners ("degenerated face")
        if (keyword == "f" && corners.size() >= 3) pieces.push_back(1);
        if (corners.size() <= kMostCorners) {
            out << line << '\n';
            continue;
        }
        split = true;
        const std::size_t count = (corners.size() - 1 + kMostCorners - 2) / (kMostCorners - 1);
        pieces.back() = count;
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t first = k * (corners.size() - 1) / count, last = (k + 1) * (corners.size() - 1) / count;
            out << 'f';
            for (std::size_t c = first; c <= last; ++c) out << ' ' << corners[c];
            out << '\n';
        }
    }
    return split ? out.str() : text;
}

}  // namespace

FileMesh readObj(const std::string& path) {
    FileMesh out;
    const std::string text = objText(path);
    out.extraFiles = checkNumbersAndListMaterialFiles(path, text);
    // tinyobjloader's own file reading, on the text read above; MTL files beside the OBJ.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    MaterialFiles materialFiles(std::filesystem::path(path).parent_path().string());
    std::vector<std::size_t> pieces;  // per face line: how many faces tinyobjloader is given for it
    std::istringstream stream(splitLongFaces(text, pieces));
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &materialFiles,
                          /*triangulate=*/false,  // polygons are split here (appendPolygon), after their indices are checked
                          /*default_vcols_fallback=*/false))
        throw FileError(path, "cannot read it as Wavefront OBJ: " +
                                  (error.empty() ? std::string("no reason given") : lines(error)));
    if (!warning.empty()) out.warnings.push_back(lines(warning));
    long long imageBudget = kMostImageTexels;  // for all of the file's maps together
    const std::vector<MaterialKeys> keys = materialFiles.keys(materials);
    for (std::size_t k = 0; k < materials.size(); ++k)
        out.materials.push_back(convertMaterial(materials[k], keys[k], k, path, out, imageBudget));

    const std::size_t vertexCount = attrib.vertices.size() / 3, normalCount = attrib.normals.size() / 3;
    const std::string fileName = std::filesystem::path(path).stem().string();
    std::map<std::string, std::size_t> byName;  // a group named again adds to the same surface
    const std::size_t texCoordCount = attrib.texcoords.size() / 2;
    std::vector<std::map<std::array<int, 3>, std::uint32_t>> corners;  // (v, vn, vt) -> the surface's vertex
    // The faces splitLongFaces split are put together again: tinyobjloader keeps the file's faces
    // in order, shape after shape.
    std::size_t faceCount = 0;
    for (const tinyobj::shape_t& shape : shapes) faceCount += shape.mesh.num_face_vertices.size();
    const bool joined = std::any_of(pieces.begin(), pieces.end(), [](std::size_t n) { return n > 1; });
    if (joined && faceCount != std::accumulate(pieces.begin(), pieces.end(), std::size_t{0}))
        throw FileError(path, "has a face of more than 255 corners that could not be read in one piece");
    std::size_t faceLine = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        out.skippedElements += shape.lines.num_line_vertices.size() + shape.points.indices.size();
        if (shape.mesh.num_face_vertices.empty()) continue;
        // tinyobjloader counts a face's corners in a byte: a face of 256 or more corners would
        // shift every face after it.
        std::size_t cornerCount = 0;
        for (unsigned char count : shape.mesh.num_face_vertices) cornerCount += count;
        if (cornerCount != shape.mesh.indices.size())
            throw FileError(path, "'" + (shape.name.empty() ? fileName : shape.name) +
                                      "' has a face of more than 255 corners, which this reader cannot take");
        const std::string name = shape.name.empty() ? fileName : shape.name;
        auto [found, added] = byName.emplace(name, out.surfaces.size());
        if (added) {
            out.surfaces.emplace_back();
            out.surfaces.back().name = name;
            corners.emplace_back();
        }
        FileSurface& surface = out.surfaces[found->second];
        auto& known = corners[found->second];
        // The surface's vertex for a corner: one per position, normal and texture coordinate.
        auto vertexOf = [&](const tinyobj::index_t& index) {
            if (index.vertex_index < 0 || static_cast<std::size_t>(index.vertex_index) >= vertexCount)
                throw FileError(path, "a face of '" + name + "' names vertex " + std::to_string(index.vertex_index + 1) +
                                          " of " + std::to_string(vertexCount));
            const int normal =
                index.normal_index >= 0 && static_cast<std::size_t>(index.normal_index) < normalCount ? index.normal_index
                                                                                                       : -1;
            const int texCoord =
                index.texcoord_index >= 0 && static_cast<std::size_t>(index.texcoord_index) < texCoordCount
                    ? index.texcoord_index
                    : -1;
            const auto [at, fresh] = known.emplace(std::array<int, 3>{index.vertex_index, normal, texCoord},
                                                   static_cast<std::uint32_t>(surface.positions.size()));
            if (fresh) {
                const auto v = static_cast<std::size_t>(index.vertex_index);
                surface.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                               attrib.vertices[3 * v + 2]);
                glm::dvec3 n(0.0);
                if (normal >= 0) {
                    const auto k = static_cast<std::size_t>(normal);
                    n = glm::dvec3(attrib.normals[3 * k], attrib.normals[3 * k + 1], attrib.normals[3 * k + 2]);
                    if (!(glm::length(n) > 1e-12)) ++surface.zeroNormals;
                }
                if (normal >= 0 || !surface.normals.empty()) {
                    surface.normals.resize(surface.positions.size() - 1, glm::dvec3(0.0));
                    surface.normals.push_back(n);
                }
                if (attrib.colors.size() == attrib.vertices.size())  // "v x y z r g b", on every v line
                    surface.colors.emplace_back(srgbComponentToLinear(attrib.colors[3 * v]),
                                                srgbComponentToLinear(attrib.colors[3 * v + 1]),
                                                srgbComponentToLinear(attrib.colors[3 * v + 2]));
                if (texCoord >= 0 || !surface.texCoords.empty()) {  // vertices without vt read (0, 0)
                    glm::dvec2 uv(0.0);
                    if (texCoord >= 0) {
                        const auto k = static_cast<std::size_t>(texCoord);
                        uv = glm::dvec2(attrib.texcoords[2 * k], 1.0 - attrib.texcoords[2 * k + 1]);
                    }
                    surface.texCoords.resize(surface.positions.size() - 1, glm::dvec2(0.0));
                    surface.texCoords.push_back(uv);
                }
            }
            return at->second;
        };
        std::size_t next = 0;
        const std::size_t faces = shape.mesh.num_face_vertices.size();
        for (std::size_t f = 0; f < faces;) {
            const std::size_t face = f, parts = joined ? pieces[faceLine] : 1;
            ++faceLine;
            std::vector<std::uint32_t> polygon;
            for (std::size_t part = 0; part < parts && f < faces; ++part, ++f) {
                const std::size_t count = shape.mesh.num_face_vertices[f];
                // A piece after the first starts at the corner the one before ended at.
                for (std::size_t c = part == 0 ? 0 : 1; c < count; ++c)
                    polygon.push_back(vertexOf(shape.mesh.indices[next + c]));
                next += count;
            }
            const int material = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            const int kept = material >= 0 && static_cast<std::size_t>(material) < out.materials.size() ? material : -1;
            if (polygon.size() < 3) ++out.skippedElements;
            appendPolygon(polygon, kept, surface);
        }
    }
    for (FileSurface& surface : out.surfaces) {
        if (!surface.normals.empty()) surface.normals.resize(surface.positions.size(), glm::dvec3(0.0));
        if (!surface.texCoords.empty()) surface.texCoords.resize(surface.positions.size(), glm::dvec2(0.0));
    }
    return out;
}

}  // namespace rad
