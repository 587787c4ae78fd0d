#include "render/path_tracer.h"

#include <string>

#include "device/kernel_arguments.h"
#include "util/error.h"

namespace rad {

PathTraceResult pathTrace(const PreparedScene& scene, const View& view, const PathTraceOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the path tracer needs at least one sample per pixel");
    const std::string what = "the path tracer";
    const PixelSums out(scene.compute(), options.width, options.height, what);
    DeviceKernel<PathtraceArgs> kernel = scene.device().kernel<PathtraceArgs>("pathtrace.cl", "pathtrace");
    PathtraceArgs args;
    args.lightSampling = options.lightSampling ? 1 : 0;
    args.camera = cameraRays(view, options.width, options.height);
    args.width = static_cast<rad_uint>(options.width);
    args.height = static_cast<rad_uint>(options.height);
    args.maxBounces = options.maxBounces;
    args.seed = options.seed;
    return estimatePixels(kernel, args, out, options.width, options.height, {options.samples, options.noise},
                          "path tracing");
}

}  // namespace rad
