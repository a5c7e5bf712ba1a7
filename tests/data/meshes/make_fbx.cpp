// Writes two_materials.fbx (test data): two_materials.obj turned to FBX's default Y-up
// frame ((x, y, z) -> (x, z, -y)), so that sigchain's rule for a declared Y-up axis gives
// back the square at z = 0, through Assimp's FBX exporter as ASCII FBX 7.5 (Assimp 5.2
// cannot read back the binary FBX its exporter writes: "block offset is out of range").
//   g++ make_fbx.cpp -o /tmp/make_fbx -lassimp && (cd tests/data/meshes && /tmp/make_fbx)
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cstdio>

int main() {
    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile("two_materials.obj", 0);
    if (!read) {
        std::fprintf(stderr, "make_fbx: %s\n", importer.GetErrorString());
        return 1;
    }
    aiScene* scene = importer.GetOrphanedScene();  // ours to change
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        for (unsigned v = 0; v < scene->mMeshes[m]->mNumVertices; ++v) {
            aiVector3D& p = scene->mMeshes[m]->mVertices[v];
            p = aiVector3D(p.x, p.z, -p.y);
        }
    Assimp::Exporter exporter;
    if (exporter.Export(scene, "fbxa", "two_materials.fbx") != AI_SUCCESS) {
        std::fprintf(stderr, "make_fbx: %s\n", exporter.GetErrorString());
        return 1;
    }
    delete scene;
    return 0;
}
