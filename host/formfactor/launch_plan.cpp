#include "formfactor/launch_plan.h"

#include <algorithm>

#include "util/error.h"

namespace rad {

std::vector<Launch> planLaunches(const std::vector<RayRequest>& requests, std::uint32_t maxRays) {
    std::vector<Launch> launches;
    Launch current;
    for (const RayRequest& request : requests) {
        if (request.firstSample + request.rays > (std::uint64_t{1} << 32))
            throw InputError("more than 2^32 rays from one source");
        std::uint64_t done = 0;
        while (done < request.rays) {
            if (current.rayCount == maxRays) {
                launches.push_back(std::move(current));
                current = Launch{};
            }
            const auto take =
                static_cast<std::uint32_t>(std::min<std::uint64_t>(request.rays - done, maxRays - current.rayCount));
            RaySource source{};
            source.firstTriangle = request.firstTriangle;
            source.triangleCount = request.triangleCount;
            source.guide = request.guide;
            source.firstRay = current.rayCount;
            source.rayCount = take;
            source.firstSample = static_cast<std::uint32_t>(request.firstSample + done);
            source.scramble = request.scramble;
            source.row = request.row;
            current.sources.push_back(source);
            current.rayCount += take;
            done += take;
        }
    }
    if (current.rayCount > 0) launches.push_back(std::move(current));
    return launches;
}

}  // namespace rad
