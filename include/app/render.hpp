// Pictures of a run: 2D particles coloured by temperature in the plane; 3D an orthographic view
// of the whole box from above and aside, shaded spheres sized to the spacing drawn back to front
// with a depth cue, over the box's floor. Both with a colour bar and the time.
#pragma once

#include <string>

#include "app/image.hpp"
#include "sph/storage.hpp"

namespace num::app {

template <int Dim>
struct RenderSettings {
    Vec<double, Dim> min{}, max{};        ///< the region shown (2D: the domain with its walls)
    double spacing = 0.01;                ///< particle spacing (disc size)
    double colorMin = 0, colorMax = 100;  ///< temperatures at the ends of the colour bar
    int width = 960;                      ///< picture width in pixels
    int upAxis = Dim - 1;                 ///< 3D: the axis drawn upwards
    std::string title;
};

template <int Dim>
Image renderParticles(const sph::Storage<Dim>& s, const RenderSettings<Dim>& r, double time);

}  // namespace num::app
