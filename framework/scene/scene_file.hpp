#pragma once
// Scene files: several glTF models placed together, with lights and camera
// paths, for the renderer, benchmarks and tests.
//
// # Scene file format (JSON)
//
// ```json
// {
//   "objects": [
//     {
//       "gltf": "models/DamagedHelmet.gltf",
//       "name": "helmet",
//       "translation": [0, 1, 0],
//       "rotation": [0, 0, 0, 1],
//       "scale": 2,
//       "shading": "decoupled"
//     },
//     { "gltf": "models/Duck.glb", "rotationDegrees": [0, 90, 0], "scale": [1, 2, 1] }
//   ],
//   "lights": [
//     { "type": "directional", "direction": [-1, -1, -1], "color": [1, 1, 1], "intensity": 3 },
//     { "type": "point", "position": [0, 3, 0], "intensity": 20, "range": 10 },
//     { "type": "spot", "position": [0, 3, 3], "direction": [0, -1, -1],
//       "innerConeAngle": 0.2, "outerConeAngle": 0.5, "name": "key" }
//   ],
//   "cameraPaths": [
//     { "name": "orbit", "type": "orbit", "center": [0, 1, 0], "radius": 4, "height": 1, "seconds": 10 },
//     { "name": "fly", "type": "keys", "keys": [
//         { "t": 0, "position": [0, 1, 5], "target": [0, 1, 0] },
//         { "t": 4, "position": [3, 2, 3], "target": [0, 1, 0] } ] }
//   ]
// }
// ```
//
// objects (required, may be empty): each instances every node of one glTF file.
// - gltf (required): .gltf or .glb path, relative to the scene file (or absolute).
//   A file named by several objects is loaded once, and its meshes, materials
//   and textures are stored once in the Scene.
// - name: prefixed to the glTF's instance names as "name/node"; default: the file's stem.
// - translation [x,y,z] (default 0), rotation: a unit quaternion [x,y,z,w] as in
//   glTF, or rotationDegrees [x,y,z]: Euler angles in degrees applied about X,
//   then Y, then Z (fixed axes); not both. scale: a number or [x,y,z] (default 1).
//   The object's matrix is T * R * S, applied on top of the glTF's own node transforms.
// - shading: "auto" | "decoupled" | "forward"; overrides every node's extras.shading.
//
// lights: added to those the glTF files bring (KHR_lights_punctual), with the
// extension's fields and units: type "directional" | "point" | "spot" (required),
// color [r,g,b] linear (default 1), intensity (default 1; lux for directional,
// candela otherwise), range (point/spot, default 0 = infinite), position [x,y,z]
// (point/spot, default 0), direction [x,y,z] (directional/spot, default [0,0,-1],
// normalized), innerConeAngle / outerConeAngle in radians (spot, defaults 0 and
// pi/4), name.
//
// cameraPaths: see camera_path.hpp for the motion.
// - type "orbit": center [x,y,z] (default 0), radius (> 0, required), height
//   (default 0), seconds per revolution (> 0, default 10).
// - type "keys": keys, at least one, each { "t": seconds, "position": [x,y,z],
//   "target": [x,y,z] }, t strictly increasing.
// - name: default "path N".
//
// Unknown properties are errors (a misspelt "shadng" would otherwise be
// silently ignored). Errors name the scene file, the JSON path and, for a
// glTF that fails, that file's own message.
#include <filesystem>
#include <vector>

#include <shadelgraph/scene/camera_path.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene {

struct SceneFile {
  Scene scene;  // every object's instances, lights and cameras, in object order; warnings prefixed with the glTF's file name
  std::vector<CameraPath> cameraPaths;
};

// Throws SceneError.
SceneFile loadSceneFile(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace sg::scene
