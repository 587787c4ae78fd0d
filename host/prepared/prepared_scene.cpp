#include "prepared/prepared_scene.h"

#include "light/light_sampling.h"
#include "mesh/patch_textures.h"
#include "util/stopwatch.h"

namespace rad {

PreparedScene::PreparedScene(Scene scene, const MeshOptions& options, const DeviceChoice& device,
                             const HostStageCheck& check)
    : PreparedScene(
          std::move(scene), options, [&device] { return ComputeContext::open(device.selector, device.profiling); },
          check) {}

PreparedScene::PreparedScene(Scene scene, const MeshOptions& options, std::shared_ptr<ComputeContext> compute)
    : PreparedScene(std::move(scene), options, [&compute] { return std::move(compute); }, {}) {}

PreparedScene::PreparedScene(Scene scene, const MeshOptions& options,
                             const std::function<std::shared_ptr<ComputeContext>()>& open, const HostStageCheck& check)
    : scene_(std::move(scene)) {
    Stopwatch stage;
    mesh_ = buildMesh(scene_, options);
    {
        const PatchTextureMeans textures = patchTextureMeans(scene_, mesh_);
        emitters_ = findEmitters(scene_, mesh_, textures);
        patches_ = buildPatchSystem(scene_, mesh_, textures, emitters_);
    }
    meshSeconds_ = stage.seconds();
    if (check) check(*this);

    stage = Stopwatch();
    bvh_ = buildWideBvh(mesh_.faces);
    bvhSeconds_ = stage.seconds();

    stage = Stopwatch();
    compute_ = open();
    device_ = std::make_unique<DeviceScene>(*compute_, deviceInputs());
    deviceSeconds_ = stage.seconds();
}

DeviceSceneInputs PreparedScene::deviceInputs() const {
    return {scene_,
            mesh_,
            bvh_,
            patches_.reflectance,
            patches_.emission,
            {emitters_.punctualLights(), surfaceLightTable(scene_, mesh_, emitters_)},
            &patches_.shadingColour};
}

void PreparedScene::addEmitter(std::unique_ptr<Emitter> emitter) {
    emitter->addPatchEmission(patches_.emission);
    emitters_.add(std::move(emitter));
    device_->updateLights(deviceInputs());
}

}  // namespace rad
