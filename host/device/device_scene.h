#pragma once
// The scene on the device: everything the kernels read that does not change during a command,
// uploaded once and owned here. The arrays are those kernels/scene_data.h declares
// (RAD_SCENE_ARGS), in its order: the BVH, the faces' patch grids, the triangles rays start from
// with their area tables (mesh/sampling_tables.h), the textures and alpha masks
// (device/device_textures.h), mirrors and glass (device/specular_faces.h), the faces'
// materials, the lights the kernels sample (punctual lights with their tree, emitting patches)
// and the light from outside (device/device_environment.h), with a SceneInfo of the counts.
// kernel<Args>() binds them as a kernel's first arguments, again at every launch, so no caller
// binds them.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "device/device_elements.h"
#include "light/light_sampling.h"
#include "light/light_tree.h"
#include "mesh/mesh.h"
#include "mesh/sampling_tables.h"
#include "scene/scene.h"
#include "scene_data.h"

namespace rad {

// The lights the kernels sample for direct light (light/light_sampling.h, light/light_tree.h).
struct SceneLights {
    PunctualLightSet punctual;
    SurfaceLightTable surfaces;
};

// What the scene's arrays are made from.
struct DeviceSceneInputs {
    const Scene& scene;
    const Mesh& mesh;
    const WideBvh& bvh;
    // Per patch: diffuse reflectance (what textured mirrors and rough metals take their F0 from,
    // and a face's shown reflectance) and emitted radiance (prepared/patch_system.h).
    const std::vector<glm::vec3>& patchReflectance;
    const std::vector<glm::vec3>& patchEmission;
    SceneLights lights;
    // Per patch: the colour the kernels read at a hit (PatchSystem::shadingColour); null:
    // patchReflectance (a scene without specular layers).
    const std::vector<glm::vec3>* patchShadingColour = nullptr;
};

// A program file (kernels/) and whether it follows mirrors and glass (DeviceScene::program).
struct KernelSource {
    KernelSource(const char* file, bool followSpecular = true) : file(file), followSpecular(followSpecular) {}  // NOLINT
    std::string file;
    bool followSpecular = true;
};

class DeviceScene {
public:
    DeviceScene(ComputeContext& compute, const DeviceSceneInputs& inputs);

    // Uploads the faces' emission and the lights again (an emitter added after preparing:
    // PreparedScene::addEmitter).
    void updateLights(const DeviceSceneInputs& inputs);

    // The program `file` (kernels/), built for this scene: with alpha masks only where a face is
    // masked (-DRAD_ALPHA_MASKS), mirrors and glass followed only where a face is one
    // (-DRAD_SPECULAR_TRANSPORT), and specular layers drawn only where a face has one
    // (-DRAD_LAYERS), the GGX albedo table read only where layers or rough metals need it
    // (-DRAD_GGX_TABLE), and normal maps read only where a face has one (-DRAD_NORMAL_MAPS), so
    // scenes without pay nothing for them. followSpecular false:
    // mirrors and glass as the matrix solvers see them, surfaces like any other.
    cl::Program& program(const std::string& file, bool followSpecular = true) const;

    // The kernel `name` of the program `source` names, its first arguments the scene's arrays and
    // then the packs `before`; Own is the pack given at each launch. All of them are bound again
    // at every launch: the kernel reads the lights as updateLights left them, and keeps the
    // packs' buffers alive. It must not outlive this scene.
    template <typename Own, typename... Before>
    DeviceKernel<Own> kernel(const KernelSource& source, const char* name, const Before&... before) const {
        try {
            cl::Kernel kernel(program(source.file, source.followSpecular), name);
            typename DeviceKernel<Own>::BindFirst bindFirst = [this, before...](cl::Kernel& k) {
                cl_uint next = bindScene(k);
                ((next = before.bind(k, next)), ...);
                return next;
            };
            bindFirst(kernel);  // an unset buffer is refused now, before any launch
            return DeviceKernel<Own>(*compute_, std::move(kernel), std::move(bindFirst));
        } catch (const cl::Error& e) {
            throwDeviceError(e, std::string("creating the kernel ") + name);
        }
    }

    // The scene's parameter names, in order (for tests/test_kernels.cpp).
    static std::vector<std::string> argumentNames();

    ComputeContext& compute() const { return *compute_; }
    bool masked() const { return masked_; }                // whether any face is alpha-masked
    bool specularFaces() const { return specularFaces_; }  // whether any face is a mirror, metal or glass
    bool textured() const { return info_.textured != 0; }  // whether any face has a texture
    bool layered() const { return layered_; }  // whether any face has a specular layer (-DRAD_LAYERS)
    bool normalMapped() const { return normalMapped_; }  // whether any face has a normal map (-DRAD_NORMAL_MAPS)
    // How far a ray continued from a surface (reflected, refracted, gathered) leaves it, at the
    // least: 32 ulps of the scene's largest coordinate, metres.
    float lift() const { return info_.lift; }
    const EnvironmentInfo& environment() const { return info_.environment; }
    std::uint32_t patchCount() const { return patchCount_; }
    const std::vector<TriangleRun>& surfaceRuns() const { return surfaceRuns_; }  // each surface side's faces in `triangles`
    // Device memory the arrays take.
    std::uint64_t bytes() const;

    // The element mesh on the device: uploaded when first asked for, then shared for as long as
    // the same mesh (by content) is asked for, so the solver, the caustics, the camera pass and
    // the lightmap read one copy. A different mesh (a refined one) replaces it here; those who
    // hold the old one keep it alive.
    std::shared_ptr<const DeviceElements> elements(const ElementMesh& mesh) const;

private:
    cl_uint bindScene(cl::Kernel& kernel) const;
    void uploadLights(const DeviceSceneInputs& inputs);

    ComputeContext* compute_;
#define RAD_DEVICE_SCENE_ARRAY(kind, type, name) DeviceArray<type> name;
    RAD_SCENE_ARGS(RAD_DEVICE_SCENE_ARRAY)
#undef RAD_DEVICE_SCENE_ARRAY
    SceneInfo info_{};
    bool masked_ = false;
    bool specularFaces_ = false;
    bool layered_ = false;
    bool ggxTable_ = false;  // the GGX albedo table is uploaded (layers or rough metals)
    bool normalMapped_ = false;
    std::uint32_t patchCount_ = 0;
    std::vector<TriangleRun> surfaceRuns_;
    mutable std::shared_ptr<const DeviceElements> elements_;
};

}  // namespace rad
