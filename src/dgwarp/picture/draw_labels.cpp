// The text parts of a picture: the colour bar and the title (cairo's toy text API).
#include <algorithm>
#include <array>
#include <string>

#include "dgwarp/picture/cairo_handles.hpp"
#include "dgwarp/picture/picture_parts.hpp"

namespace dgwarp::picture_detail {

namespace {

constexpr Rgb text_color{0.1, 0.1, 0.1};

void select_font(cairo_t* cr, double size_px, bool bold) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size_px);
}

double text_width(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, text.c_str(), &e);
    return e.x_advance;
}

// Shrinks the current font until `text` is at most max_width wide.
void fit_font(cairo_t* cr, const std::string& text, double size_px, double max_width) {
    const double w = text_width(cr, text);
    if (w > max_width && w > 0) cairo_set_font_size(cr, size_px * max_width / w);
}

}  // namespace

void draw_colorbar(cairo_t* cr, const PictureLayout& layout, const std::string& label) {
    const double f = layout.font_px;
    const double plot_right = layout.plot[0] + layout.plot[2];
    const double plot_top = layout.plot[1], plot_bottom = layout.plot[1] + layout.plot[3];
    const double x = plot_right + 1.2 * f, bar_w = 1.2 * f;
    const double room_right = layout.width - x - 0.3 * f;  // for text starting at the bar
    // The bar spans the plot's height less the label above and the inverted swatch below.
    const double top = plot_top + 2.0 * f, bottom = plot_bottom - 3.2 * f;
    if (bottom - top < 2 * f) return;  // no room in a tiny picture

    cairo_save(cr);
    const std::span<const Rgb> map = colors_of_map();
    Pattern gradient(cairo_pattern_create_linear(0, bottom, 0, top));
    for (std::size_t k = 0; k < map.size(); ++k)
        cairo_pattern_add_color_stop_rgb(gradient.get(), static_cast<double>(k) / (map.size() - 1), map[k].r,
                                         map[k].g, map[k].b);
    cairo_rectangle(cr, x, top, bar_w, bottom - top);
    cairo_set_source(cr, gradient.get());
    cairo_fill_preserve(cr);
    set_color(cr, text_color);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);

    select_font(cr, 0.9 * f, false);
    const std::array<std::pair<double, const char*>, 5> ticks = {
        {{0.0, "0"}, {0.25, "0.25"}, {0.5, "0.5"}, {0.75, "0.75"}, {1.0, "1"}}};
    for (const auto& [value, text] : ticks) {
        const double y = bottom - value * (bottom - top);
        cairo_move_to(cr, x + bar_w, y);
        cairo_line_to(cr, x + bar_w + 0.35 * f, y);
        cairo_stroke(cr);
        cairo_move_to(cr, x + bar_w + 0.55 * f, y + 0.32 * f);
        cairo_show_text(cr, text);
    }

    // The inverted colour is not on the map: a swatch of its own below it.
    const double swatch_top = bottom + 1.5 * f;
    cairo_rectangle(cr, x, swatch_top, bar_w, bar_w);
    set_color(cr, inverted_color);
    cairo_fill_preserve(cr);
    set_color(cr, text_color);
    cairo_stroke(cr);
    const std::string inverted = "inverted";
    fit_font(cr, inverted, 0.9 * f, room_right - bar_w - 0.55 * f);
    cairo_move_to(cr, x + bar_w + 0.55 * f, swatch_top + 0.5 * bar_w + 0.32 * f);
    cairo_show_text(cr, inverted.c_str());

    select_font(cr, f, false);
    fit_font(cr, label, f, room_right);
    cairo_move_to(cr, x, top - 0.8 * f);
    cairo_show_text(cr, label.c_str());
    cairo_restore(cr);
}

void draw_title(cairo_t* cr, const PictureLayout& layout, const std::string& title) {
    const double f = layout.font_px;
    cairo_save(cr);
    select_font(cr, 1.15 * f, true);
    fit_font(cr, title, 1.15 * f, layout.width - 1.6 * f);
    const double w = text_width(cr, title);
    set_color(cr, text_color);
    cairo_move_to(cr, std::max(0.8 * f, layout.plot[0] + 0.5 * (layout.plot[2] - w)), layout.plot[1] - 0.7 * f);
    cairo_show_text(cr, title.c_str());
    cairo_restore(cr);
}

}  // namespace dgwarp::picture_detail
