#include "scene/environment_map.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "shared_math.h"
#include "util/error.h"
#include "util/fnv.h"
#include "util/shares.h"

namespace rad {
namespace {

std::string texelName(int x, int y) {
    return "texel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

}  // namespace

EnvironmentMap loadEnvironmentMap(const std::string& path, double strength) {
    if (!std::ifstream(path, std::ios::binary)) throw FileError(path, "cannot open the environment map");
    EnvironmentMap map;
    map.path = path;
    map.strength = strength;
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
        const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
        if (width < 1 || height < 1) throw FileError(path, "the environment map's data window is empty");
        if (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > kMaxEnvironmentTexels)
            throw FileError(path, "the environment map has " + std::to_string(width) + " x " + std::to_string(height) +
                                      " texels, more than the " + std::to_string(kMaxEnvironmentTexels) +
                                      " this program reads; scale it down");
        const Imf::ChannelList& channels = header.channels();
        const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        if (!rgb && (channels.findChannel("RY") || channels.findChannel("BY")))
            throw FileError(path,
                            "the environment map is stored as luminance and chroma (Y, RY, BY), which this "
                            "program does not read: save it as RGB");
        const bool grey = !rgb && channels.findChannel("Y");
        if (!rgb && !grey) throw FileError(path, "the environment map has neither R, G and B channels nor a Y channel");
        map.width = static_cast<int>(width);
        map.height = static_cast<int>(height);
        map.radiance.assign(static_cast<std::size_t>(width * height), glm::vec3(0.0f));
        char* base = reinterpret_cast<char*>(map.radiance.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.y) * width + window.min.x) *
                         static_cast<std::ptrdiff_t>(sizeof(glm::vec3));
        const std::size_t xStride = sizeof(glm::vec3), yStride = xStride * static_cast<std::size_t>(width);
        Imf::FrameBuffer frame;
        if (rgb) {
            frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
            frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
            frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        } else {
            frame.insert("Y", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (grey)
            for (glm::vec3& texel : map.radiance) texel = glm::vec3(texel.x);
    } catch (const FileError&) {
        throw;
    } catch (const std::exception& e) {
        throw FileError(path, std::string("cannot read the environment map as OpenEXR: ") + e.what());
    }
    bool lit = false;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const glm::vec3 texel = map.at(x, y);
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(texel[c]) || texel[c] < 0.0f)
                    throw FileError(path, "the environment map's " + texelName(x, y) +
                                              " is not a radiance (negative, infinite or NaN)");
            lit = lit || texel != glm::vec3(0.0f);
        }
    if (!lit) throw FileError(path, "the environment map is black everywhere: it lights nothing");
    for (glm::vec3& texel : map.radiance) {
        texel *= static_cast<float>(strength);
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(texel[c]))
                throw FileError(path, "the environment map times --environment-strength overflows single precision");
    }
    return map;
}

glm::dvec2 environmentCoordinates(const glm::dvec3& d) {
    const double u = 0.5 + std::atan2(d.z, d.x) / (2.0 * kPi);
    const double t = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
    return {u, t};
}

glm::dvec3 environmentDirection(double u, double t) {
    const double phi = 2.0 * kPi * (u - 0.5), theta = kPi * t;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

glm::dvec3 environmentRadiance(const EnvironmentMap& map, const glm::dvec3& direction) {
    const glm::dvec2 ut = environmentCoordinates(direction);
    const double x = ut.x * map.width - 0.5, y = ut.y * map.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto column = [&](double i) {
        const long long w = map.width;
        return static_cast<int>(((static_cast<long long>(i) % w) + w) % w);
    };
    const auto row = [&](double j) { return static_cast<int>(std::clamp(j, 0.0, map.height - 1.0)); };
    const int xa = column(x0), xb = column(x0 + 1.0), ya = row(y0), yb = row(y0 + 1.0);
    return (1.0 - fy) * ((1.0 - fx) * glm::dvec3(map.at(xa, ya)) + fx * glm::dvec3(map.at(xb, ya))) +
           fy * ((1.0 - fx) * glm::dvec3(map.at(xa, yb)) + fx * glm::dvec3(map.at(xb, yb)));
}

double environmentTexelSolidAngle(const EnvironmentMap& map, int y) {
    const double top = kPi * y / map.height, bottom = kPi * (y + 1) / map.height;
    return (2.0 * kPi / map.width) * (std::cos(top) - std::cos(bottom));
}

glm::dvec3 environmentIntegral(const EnvironmentMap& map) {
    // Across a row the filter's weights sum to one texel each, so a row's texels count by their
    // sum over the width. Down the image, row y counts by the integral of its "hat" (linear
    // between the row centres next to it, flat beyond the first and last centres) times
    // 2 pi^2 sin(pi t), in closed form: F and G are the antiderivatives of sin(pi t) and
    // t sin(pi t).
    const auto F = [](double t) { return -std::cos(kPi * t) / kPi; };
    const auto G = [](double t) { return -t * std::cos(kPi * t) / kPi + std::sin(kPi * t) / (kPi * kPi); };
    const int h = map.height;
    std::vector<double> rowWeight(h, 0.0);
    const auto centre = [h](int y) { return (y + 0.5) / h; };
    rowWeight[0] += F(centre(0)) - F(0.0);
    rowWeight[h - 1] += F(1.0) - F(centre(h - 1));
    for (int y = 0; y + 1 < h; ++y) {
        const double a = centre(y), b = centre(y + 1), dF = F(b) - F(a), dG = G(b) - G(a);
        rowWeight[y] += h * (b * dF - dG);
        rowWeight[y + 1] += h * (dG - a * dF);
    }
    glm::dvec3 integral(0.0);
    for (int y = 0; y < h; ++y) {
        glm::dvec3 row(0.0);
        for (int x = 0; x < map.width; ++x) row += glm::dvec3(map.at(x, y));
        integral += (2.0 * kPi * kPi / map.width) * rowWeight[y] * row;
    }
    return integral;
}

EnvironmentSampling environmentSampling(const EnvironmentMap& map) {
    const int w = map.width, h = map.height;
    std::vector<double> mean(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3& c = map.at(x, y);
            mean[static_cast<std::size_t>(y) * w + x] = (static_cast<double>(c.x) + c.y + c.z) / 3.0;
        }
    std::vector<double> weight(mean.size()), rowWeight(h, 0.0);
    for (int y = 0; y < h; ++y) {
        const double solidAngle = environmentTexelSolidAngle(map, y);
        for (int x = 0; x < w; ++x) {
            double largest = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int yy = std::clamp(y + dy, 0, h - 1), xx = ((x + dx) % w + w) % w;
                    largest = std::max(largest, mean[static_cast<std::size_t>(yy) * w + xx]);
                }
            weight[static_cast<std::size_t>(y) * w + x] = largest * solidAngle;
            rowWeight[y] += largest * solidAngle;
        }
    }
    EnvironmentSampling sampling;
    sampling.rows.reserve(h);
    appendShares(rowWeight.data(), rowWeight.size(), sampling.rows);
    sampling.columns.reserve(weight.size());
    for (int y = 0; y < h; ++y) appendShares(weight.data() + static_cast<std::size_t>(y) * w, w, sampling.columns);
    return sampling;
}

double environmentPdf(const EnvironmentMap& map, const EnvironmentSampling& sampling, const glm::dvec3& direction) {
    const glm::dvec2 ut = environmentCoordinates(direction);
    const int x = std::clamp(static_cast<int>(std::floor(ut.x * map.width)), 0, map.width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(ut.y * map.height)), 0, map.height - 1);
    const double p = shareOf(sampling.rows.data(), map.height, y) *
                     shareOf(sampling.columns.data() + static_cast<std::size_t>(y) * map.width, map.width, x);
    return p / environmentTexelSolidAngle(map, y);
}

std::uint64_t environmentFingerprint(const EnvironmentMap& map) {
    Fnv1a hash;
    hash.add(map.width).add(map.height).add(map.strength);
    hash.add(map.radiance.data(), map.radiance.size() * sizeof(glm::vec3));
    return hash.value();
}

}  // namespace rad
