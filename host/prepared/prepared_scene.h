#pragma once
// The scene as every command, bench program and test needs it: loaded, meshed into patches,
// its emitters found, the per-patch system built, its BVH built and uploaded with the mesh to
// an OpenCL device. Built once; everything downstream (estimators, solvers, renderers) takes a
// `const PreparedScene&` instead of the five objects it holds. The device context is shared,
// not owned alone: tests prepare many scenes on one context.

#include <functional>
#include <memory>
#include <string>

#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "light/emitter.h"
#include "mesh/mesh.h"
#include "device/device_scene.h"
#include "prepared/patch_system.h"
#include "scene/scene.h"

namespace rad {

class PreparedScene;

// Called when the host's part is ready (mesh, emitters, patch system) and before the BVH, the
// device and the upload: where a command refuses, or warns about, what it can tell from the
// mesh alone, before any device work. bvh(), compute() and device() are not ready yet.
using HostStageCheck = std::function<void(const PreparedScene&)>;

// Which device to open, when none is given.
struct DeviceChoice {
    std::string selector;    // --device: index, cpu, gpu or part of a name; empty: the default
    bool profiling = false;  // time every kernel on the device (bench programs)
};

class PreparedScene {
public:
    // Meshes `scene`, builds its BVH, then opens the chosen device and uploads. Throws
    // InputError for a mesh beyond options.maxPatches, DeviceError when the device fails.
    PreparedScene(Scene scene, const MeshOptions& options, const DeviceChoice& device,
                  const HostStageCheck& check = {});
    // The same on a context already open.
    PreparedScene(Scene scene, const MeshOptions& options, std::shared_ptr<ComputeContext> compute);

    PreparedScene(const PreparedScene&) = delete;
    PreparedScene& operator=(const PreparedScene&) = delete;

    // Adds an emitter the scene's surfaces do not make (tests; lights the command line adds),
    // and takes its patch emission into the per-patch system and its lights onto the device.
    void addEmitter(std::unique_ptr<Emitter> emitter);

    const Scene& scene() const { return scene_; }
    const Mesh& mesh() const { return mesh_; }
    const Emitters& emitters() const { return emitters_; }
    const PatchSystem& patches() const { return patches_; }
    const WideBvh& bvh() const { return bvh_; }
    ComputeContext& compute() const { return *compute_; }
    const DeviceScene& device() const { return *device_; }

    // Seconds spent meshing (with the emitters and the patch system), building the BVH, and
    // opening the device and uploading.
    double meshSeconds() const { return meshSeconds_; }
    double bvhSeconds() const { return bvhSeconds_; }
    double deviceSeconds() const { return deviceSeconds_; }

private:
    DeviceSceneInputs deviceInputs() const;

    PreparedScene(Scene scene, const MeshOptions& options, const std::function<std::shared_ptr<ComputeContext>()>& open,
                  const HostStageCheck& check);

    Scene scene_;
    Mesh mesh_;
    Emitters emitters_;
    PatchSystem patches_;
    WideBvh bvh_;
    std::shared_ptr<ComputeContext> compute_;
    std::unique_ptr<DeviceScene> device_;
    double meshSeconds_ = 0.0, bvhSeconds_ = 0.0, deviceSeconds_ = 0.0;
};

}  // namespace rad
