"""The Cornell box's view factors and heat exchange, from Python (docs/guide/python.md)."""
import os
import radiosity

scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "cornell-box.gltf")
vf = radiosity.view_factors(scene, rays=100_000)  # as `radiosity viewfactors SCENE --rays 100000`
print(vf.to_csv(), end="")                          # the program's CSV, the same bits
print("row sums:", dict(zip(vf.names, vf.matrix.sum(axis=1).round(4))))
heat = radiosity.exchange(scene, properties={"light": {"emissivity": 0.9, "temperature": 600}},
                          default_emissivity=0.8, default_temperature=300, rays=100_000)
for name, q, e in zip(heat.names, heat.net_heat, heat.net_heat_stderr):
    print(f"{name:12s} net heat {q:9.3f} W +- {e:.2g}")
