#pragma once
// The scene on the device: the BVH, the faces' patch grids, and the triangles rays start from
// with the area tables that spread rays over a surface (mesh/sampling_tables.h). Uploaded once
// and read by every kernel that traces rays. The buffers are those kernels/scene_data.h
// declares, in its order; kernel() binds them as a kernel's first arguments, so no caller binds
// them one by one.

#include <cstdint>
#include <vector>

#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "mesh/mesh.h"
#include "mesh/sampling_tables.h"
#include "prepared/device_environment.h"
#include "scene/scene.h"
#include "scene_data.h"

namespace rad {

class DeviceScene {
public:
    // `scene`: its textures and alpha masks (none without it); `patchReflectance`: per patch, what
    // textured mirrors and rough metals take their F0 from (prepared/specular_faces.h).
    DeviceScene(ComputeContext& compute, const Mesh& mesh, const WideBvh& bvh, const Scene* scene = nullptr,
                const std::vector<glm::vec3>* patchReflectance = nullptr);

#define RAD_DEVICE_SCENE_BUFFER(type, name) cl::Buffer name;
    RAD_SCENE_BUFFERS(RAD_DEVICE_SCENE_BUFFER)
#undef RAD_DEVICE_SCENE_BUFFER

    // How many arguments the scene takes: a kernel's own arguments start at this index.
#define RAD_COUNT_SCENE_BUFFER(type, name) +1
    static constexpr cl_uint kArguments = 0 RAD_SCENE_BUFFERS(RAD_COUNT_SCENE_BUFFER);
#undef RAD_COUNT_SCENE_BUFFER

    // The kernel `name` of `program`, with the scene's buffers bound as its first arguments
    // (the kernel declares them with RAD_SCENE_PARAMS).
    cl::Kernel kernel(cl::Program& program, const char* name) const;

    // A program that traces this scene, built for it: with alpha masks only where a face is
    // masked (-DRAD_ALPHA_MASKS), and mirrors and glass followed only where a face is one
    // (-DRAD_SPECULAR_TRANSPORT), so scenes without pay nothing for them. followSpecular false:
    // mirrors and glass as the matrix solvers see them, surfaces like any other.
    cl::Program& program(ComputeContext& compute, const std::string& mainFile, bool followSpecular = true) const {
        std::string options = masked ? "-DRAD_ALPHA_MASKS" : "";
        if (specularFaces && followSpecular)
            options += options.empty() ? "-DRAD_SPECULAR_TRANSPORT" : " -DRAD_SPECULAR_TRANSPORT";
        return compute.program(mainFile, options);
    }
    bool masked = false;  // whether any face is alpha-masked

    bool specularFaces = false;  // whether any face is specular
    // How far a ray continued from a surface (reflected, refracted, gathered) leaves it, at the
    // least: 32 ulps of the scene's largest coordinate, metres.
    float lift = 0.0f;

    std::vector<TriangleRun> surfaceRuns;  // where each surface side's faces are in `triangles`
    std::vector<FaceTexture> faceTextures;  // per face (one entry when none is textured)
    bool textured = false;                  // whether any face has a texture
    DeviceEnvironment environment;          // the sky or environment map (none without `scene`)
    std::uint32_t patchCount = 0;
    std::uint64_t bytes = 0;  // device memory these buffers take
    MemoryReservation reservation;
};

}  // namespace rad
