// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot: the colours (colour maps and their lookup table, colour-bar
// labels) and the camera of field pictures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>

#include "pdfem_plot.h"
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

namespace pdfem_plot
{
  namespace
  {
    // Samples the colour map at t in [0, 1].
    using Colormap = std::function<std::array<double, 3>(double)>;

    Colormap
    viridis_map()
    {
      // The viridis colour map at t = 0, 0.1, ..., 1, interpolated linearly in
      // RGB.
      static const unsigned int stops[11] = {0x440154,
                                             0x482475,
                                             0x414487,
                                             0x355f8d,
                                             0x2a788e,
                                             0x21918c,
                                             0x22a884,
                                             0x44bf70,
                                             0x7ad151,
                                             0xbddf26,
                                             0xfde725};
      return [](double t) {
        t                       = std::clamp(t, 0.0, 1.0) * 10.0;
        const int             i = std::min(static_cast<int>(t), 9);
        const double          f = t - i;
        std::array<double, 3> rgb{};
        for (int c = 0; c < 3; ++c)
          {
            const int    shift = 16 - 8 * c;
            const double a     = ((stops[i] >> shift) & 0xff) / 255.0,
                         b     = ((stops[i + 1] >> shift) & 0xff) / 255.0;
            rgb[c]             = a + f * (b - a);
          }
        return rgb;
      };
    }

    Colormap
    coolwarm_map()
    {
      // Moreland's diverging "cool to warm" map, interpolated by VTK in its
      // diverging colour space.
      vtkSmartPointer<vtkColorTransferFunction> ctf =
        vtkSmartPointer<vtkColorTransferFunction>::New();
      ctf->SetColorSpaceToDiverging();
      ctf->AddRGBPoint(0.0, 0.230, 0.299, 0.754);
      ctf->AddRGBPoint(1.0, 0.706, 0.016, 0.150);
      return [ctf](double t) {
        std::array<double, 3> rgb{};
        ctf->GetColor(std::clamp(t, 0.0, 1.0), rgb.data());
        return rgb;
      };
    }
  } // namespace

  // A 256-colour table on [lo, hi]. For coolwarm the white middle sits at 0
  // when the range contains 0 (so the sign of a value can be read off the
  // colour), else at the middle of the range.
  vtkSmartPointer<vtkLookupTable>
  make_lookup_table(const std::string &name, double lo, double hi)
  {
    const bool straddles_zero = lo < 0.0 && hi > 0.0;
    const bool coolwarm =
      name == "coolwarm" || (name == "auto" && straddles_zero);
    const Colormap map  = coolwarm ? coolwarm_map() : viridis_map();
    const double   half = std::max(std::abs(lo), std::abs(hi));

    const int n   = 256;
    auto      lut = vtkSmartPointer<vtkLookupTable>::New();
    lut->SetNumberOfTableValues(n);
    lut->SetTableRange(lo, hi);
    for (int i = 0; i < n; ++i)
      {
        const double v = lo + (i + 0.5) / n * (hi - lo);
        double       t = (i + 0.5) / n;
        if (coolwarm && straddles_zero)
          t = 0.5 + 0.5 * v / half;
        const auto rgb = map(t);
        lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
      }
    lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
    return lut;
  }

  // Parallel-projection camera looking from direction `from` (towards the
  // centre of `bounds`), with the box bounds[0..5] filling the viewport of
  // aspect ratio `aspect` (width/height) up to `margin`.
  void
  fit_camera(vtkCamera            *camera,
             const double          bounds[6],
             std::array<double, 3> from,
             std::array<double, 3> up,
             double                aspect,
             double                margin)
  {
    auto dot = [](const std::array<double, 3> &a,
                  const std::array<double, 3> &b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    auto cross = [](const std::array<double, 3> &a,
                    const std::array<double, 3> &b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1],
                                   a[2] * b[0] - a[0] * b[2],
                                   a[0] * b[1] - a[1] * b[0]};
    };
    auto normalize = [&](std::array<double, 3> a) {
      const double n = std::sqrt(dot(a, a));
      for (double &x : a)
        x /= n;
      return a;
    };
    from = normalize(from);
    const std::array<double, 3> view{-from[0], -from[1], -from[2]};
    const std::array<double, 3> right = normalize(cross(view, up));
    up                                = cross(right, view);

    const std::array<double, 3> centre{(bounds[0] + bounds[1]) / 2,
                                       (bounds[2] + bounds[3]) / 2,
                                       (bounds[4] + bounds[5]) / 2};
    double u0 = std::numeric_limits<double>::max(), u1 = -u0, v0 = u0, v1 = -u0;
    for (int corner = 0; corner < 8; ++corner)
      {
        const std::array<double, 3> p{bounds[corner & 1] - centre[0],
                                      bounds[2 + ((corner >> 1) & 1)] -
                                        centre[1],
                                      bounds[4 + ((corner >> 2) & 1)] -
                                        centre[2]};
        u0 = std::min(u0, dot(p, right));
        u1 = std::max(u1, dot(p, right));
        v0 = std::min(v0, dot(p, up));
        v1 = std::max(v1, dot(p, up));
      }
    std::array<double, 3> focal{};
    for (int c = 0; c < 3; ++c)
      focal[c] = centre[c] + right[c] * (u0 + u1) / 2 + up[c] * (v0 + v1) / 2;
    double scale = std::max((v1 - v0) / 2, (u1 - u0) / 2 / aspect) * margin;
    const double diagonal =
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    if (!(scale > 0))
      scale = diagonal > 0 ? diagonal / 2 : 1.0;
    const double distance = std::max(diagonal, scale) * 4 + 1.0;

    camera->ParallelProjectionOn();
    camera->SetFocalPoint(focal.data());
    camera->SetPosition(focal[0] + from[0] * distance,
                        focal[1] + from[1] * distance,
                        focal[2] + from[2] * distance);
    camera->SetViewUp(up.data());
    camera->SetParallelScale(scale);
  }

  // Colour-bar labels: round values (see nice_ticks) inside [lo, hi], as many
  // as fit along a bar of length_px pixels, plus lo and hi themselves where
  // they fit (with_ends).
  std::vector<double>
  bar_labels(double lo,
             double hi,
             double length_px,
             double font_px,
             bool   with_ends)
  {
    auto text_px = [&](double v) {
      char text[64];
      std::snprintf(text, sizeof(text), "%.3g", v);
      return 0.62 * std::strlen(text) * font_px;
    };
    auto fits = [&](const std::vector<double> &values) {
      for (std::size_t i = 0; i + 1 < values.size(); ++i)
        if ((values[i + 1] - values[i]) / (hi - lo) * length_px <
            (text_px(values[i]) + text_px(values[i + 1])) / 2 + 1.5 * font_px)
          return false;
      return true;
    };
    for (int max_intervals = 8; max_intervals >= 1; --max_intervals)
      {
        const Ticks         t      = nice_ticks(lo, hi, max_intervals);
        std::vector<double> values = ticks_inside(lo, hi, t.step);
        const double        eps    = 1e-9 * (hi - lo);
        if (values.empty() || !fits(values))
          continue;
        if (!with_ends)
          {
            if (values.size() >= 2)
              return values;
            continue;
          }
        if (values.front() - lo > eps)
          {
            values.insert(values.begin(), lo);
            if (!fits(values))
              values.erase(values.begin());
          }
        if (hi - values.back() > eps)
          {
            values.push_back(hi);
            if (!fits(values))
              values.pop_back();
          }
        if (values.size() >= 2)
          return values;
      }
    return {lo, hi};
  }

  int
  decimals_for_step(double step)
  {
    if (!(step > 0.0) || !std::isfinite(step))
      return 0;
    return std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)),
                      0,
                      12);
  }
} // namespace pdfem_plot
