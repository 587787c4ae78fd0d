// STL (scene/mesh_readers.h), binary or ASCII. A binary file is one whose size is exactly 84
// bytes plus 50 a triangle, whatever its header says (binary exporters often begin it with
// "solid" too); otherwise a file that begins with "solid" is read as ASCII.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/mesh_readers.h"
#include "util/error.h"

namespace rad {
namespace {

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot be opened for reading");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

float littleEndianFloat(const char* p) {
    std::uint32_t bits = 0;
    for (int k = 3; k >= 0; --k) bits = (bits << 8) | static_cast<unsigned char>(p[k]);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

std::uint32_t littleEndianU32(const char* p) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(p[k]);
    return v;
}

void addCorner(FileSurface& surface, const glm::dvec3& p, const std::string& path, std::size_t triangle) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw FileError(path, "triangle " + std::to_string(triangle + 1) + " has a corner that is not a finite point");
    surface.positions.push_back(p);
}

void readBinary(const std::string& bytes, const std::string& path, FileSurface& surface, std::uint64_t count) {
    for (std::uint64_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
        for (int c = 0; c < 3; ++c) {
            const char* corner = record + 12 + 12 * c;  // after the facet normal
            addCorner(surface,
                      glm::dvec3(littleEndianFloat(corner), littleEndianFloat(corner + 4), littleEndianFloat(corner + 8)),
                      path, t);
        }
        const auto first = static_cast<std::uint32_t>(3 * t);
        surface.triangles.push_back({first, first + 1, first + 2});
    }
}

// Tokens of an ASCII STL, with the line each is on, for messages.
class AsciiStl {
public:
    AsciiStl(const std::string& bytes, const std::string& path) : text_(bytes), path_(path) {}

    void read(FileSurface& surface) {
        expect("solid");
        skipLine();  // the solid's name, which may hold spaces
        for (;;) {
            std::string word = next();
            if (word == "endsolid") {
                skipLine();
                word = next();
                if (word.empty()) return;
                if (word != "solid") fail("expected 'solid' or the end of the file, found '" + word + "'");
                skipLine();  // another solid in the same file: the same surface
                continue;
            }
            if (word.empty() && !surface.triangles.empty()) {  // some writers stop without endsolid
                missingEnd_ = true;
                return;
            }
            if (word != "facet") fail("expected 'facet' or 'endsolid', found '" + (word.empty() ? "the end of the file" : word) + "'");
            expect("normal");
            for (int k = 0; k < 3; ++k) number();  // the facet normal: not read (the winding says the front)
            expect("outer");
            expect("loop");
            const auto first = static_cast<std::uint32_t>(surface.positions.size());
            for (int c = 0; c < 3; ++c) {
                expect("vertex");
                const double x = number(), y = number(), z = number();
                addCorner(surface, glm::dvec3(x, y, z), path_, surface.triangles.size());
            }
            expect("endloop");
            expect("endfacet");
            surface.triangles.push_back({first, first + 1, first + 2});
        }
    }

    bool missingEnd() const { return missingEnd_; }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw FileError(path_, "line " + std::to_string(line_) + ": " + problem);
    }

    std::string next() {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
            if (text_[at_] == '\n') ++line_;
            ++at_;
        }
        const std::size_t start = at_;
        while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
        return text_.substr(start, at_ - start);
    }

    void skipLine() {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    }

    void expect(const char* word) {
        const std::string found = next();
        if (found != word) fail(std::string("expected '") + word + "', found '" + (found.empty() ? "the end of the file" : found) + "'");
    }

    double number() {
        const std::string word = next();
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        if (word.empty() || *end != '\0') fail("expected a number, found '" + (word.empty() ? "the end of the file" : word) + "'");
        return value;
    }

    const std::string& text_;
    const std::string& path_;
    std::size_t at_ = 0;
    std::size_t line_ = 1;
    bool missingEnd_ = false;
};

}  // namespace

FileMesh readStl(const std::string& path) {
    const std::string bytes = readAll(path);
    FileMesh out;
    out.surfaces.emplace_back();
    FileSurface& surface = out.surfaces.back();
    surface.name = std::filesystem::path(path).stem().string();
    const std::uint64_t declared = bytes.size() >= 84 ? littleEndianU32(bytes.data() + 80) : 0;
    const bool binary = bytes.size() >= 84 && bytes.size() == 84 + 50 * declared;
    std::size_t start = 0;
    while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
    // ASCII STL is text: control characters other than white space mean a binary file.
    const bool text = std::none_of(bytes.begin(), bytes.end(), [](char c) {
        const auto b = static_cast<unsigned char>(c);
        return b < 32 && !std::isspace(b);
    });
    if (binary) {
        readBinary(bytes, path, surface, declared);
    } else if (!text && bytes.size() > 84 + 50 * declared && declared > 0) {
        // Some writers add bytes after the triangles: the header's count is read, the rest named.
        readBinary(bytes, path, surface, declared);
        out.warnings.push_back(std::to_string(bytes.size() - 84 - 50 * declared) +
                               " bytes after the binary STL's " + std::to_string(declared) + " triangles ignored");
    } else if (!text && declared == 0 && bytes.size() > 84 && (bytes.size() - 84) % 50 == 0) {
        // A writer that streams its triangles may leave the count 0: the size says how many.
        readBinary(bytes, path, surface, (bytes.size() - 84) / 50);
        out.warnings.push_back("the binary STL's header counts 0 triangles; its size holds " +
                               std::to_string((bytes.size() - 84) / 50) + ", which are read");
    } else if (bytes.compare(start, 5, "solid") == 0 && text) {
        AsciiStl ascii(bytes, path);
        ascii.read(surface);
        if (ascii.missingEnd()) out.warnings.push_back("the ASCII STL ends without 'endsolid'");
    } else {
        const std::string header =
            bytes.size() >= 84 ? " (its header says " + std::to_string(littleEndianU32(bytes.data() + 80)) +
                                     " triangles, " + std::to_string(84 + 50 * std::uint64_t{littleEndianU32(bytes.data() + 80)}) +
                                     " bytes; the file has " + std::to_string(bytes.size()) + ")"
                               : " (the file is shorter than its 84-byte header)";
        throw FileError(path, "is neither binary STL, 84 bytes and 50 a triangle" + header +
                                  ", nor ASCII STL, text that begins with 'solid'");
    }
    return out;
}

}  // namespace rad
