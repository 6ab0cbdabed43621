#pragma once
// VTK XML unstructured grid (.vtu), binary (base64-encoded appended-free
// inline data), for ParaView. Write only.
#include <filesystem>
#include <ostream>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Writes the mesh's cells (not its markers) with point and cell data fields.
/// 2D meshes are written with z = 0. Throws MeshError when a field's size does
/// not match the mesh.
void write_vtu(std::ostream& out, const Mesh& mesh, const MeshFields& fields = {});

/// Writes to `path`, atomically.
void write_vtu(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields = {});

}  // namespace dgwarp
