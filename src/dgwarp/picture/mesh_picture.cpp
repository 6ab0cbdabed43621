#include "dgwarp/picture/mesh_picture.hpp"

#include <cmath>
#include <ostream>
#include <string>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/picture/cairo_handles.hpp"
#include "dgwarp/picture/picture_layout.hpp"
#include "dgwarp/picture/picture_parts.hpp"

namespace dgwarp {

namespace {

using namespace picture_detail;

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
    auto& out = *static_cast<std::ostream*>(closure);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
    return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

void write_mesh_picture(const std::filesystem::path& png, const Mesh& mesh, std::span<const double> cell_values,
                        const PictureOptions& options) {
    if (mesh.dim != 2) throw MeshError("pictures are 2D only (the mesh is " + std::to_string(mesh.dim) + "D)");
    validate(mesh);
    if (!cell_values.empty() && cell_values.size() != mesh.cells.size())
        throw MeshError("picture: " + std::to_string(cell_values.size()) + " cell values for " +
                        std::to_string(mesh.cells.size()) + " cells");
    if (!(std::isfinite(options.edge_width_px) && options.edge_width_px >= 0))
        throw Error("picture: edge width must be finite and >= 0, got " + std::to_string(options.edge_width_px));
    const PictureLayout layout = picture_layout(mesh, cell_values, options);

    Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, layout.width, layout.height));
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
        throw IoError(png.string(), std::string("cannot create the picture: ") +
                                        cairo_status_to_string(cairo_surface_status(surface.get())));
    {
        Context cr(cairo_create(surface.get()));
        set_color(cr.get(), background_color);
        cairo_paint(cr.get());
        draw_mesh(cr.get(), layout, mesh, cell_values, options.edge_width_px);
        if (!options.title.empty()) draw_title(cr.get(), layout, options.title);
        if (layout.colorbar) draw_colorbar(cr.get(), layout, options.colorbar_label);
        if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
            throw IoError(png.string(), std::string("cannot draw the picture: ") +
                                            cairo_status_to_string(cairo_status(cr.get())));
    }
    cairo_surface_flush(surface.get());
    write_file_atomically(png, [&](std::ostream& out) {
        const cairo_status_t status = cairo_surface_write_to_png_stream(surface.get(), write_to_stream, &out);
        if (status != CAIRO_STATUS_SUCCESS)
            throw IoError(png.string(), std::string("cannot write the PNG: ") + cairo_status_to_string(status));
    });
}

}  // namespace dgwarp
