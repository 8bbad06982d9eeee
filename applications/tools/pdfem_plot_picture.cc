// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot and pdfem-render: drawing a field picture (the model coloured by
// one scalar, a colour bar, a title; for pdfem-render also a caption, framed
// coordinate axes or a triad and outlines) and writing it as a PNG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "pdfem_plot.h"
#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkLight.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkPolyDataReader.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace pdfem_plot
{
  namespace
  {
    std::string
    fixed(double v, int decimals)
    {
      char text[64];
      std::snprintf(text, sizeof(text), "%.*f", decimals, v);
      std::string s = text;
      // No "-0.0": a value that rounds to zero is printed without its sign.
      if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos)
        s.erase(0, 1);
      return s;
    }

    // Round values of [lo, hi] (see nice_ticks) at least min_gap_px apart on
    // an axis of length_px pixels.
    std::vector<double>
    axis_ticks(double lo, double hi, double length_px, double min_gap_px)
    {
      const int max_intervals =
        std::clamp(static_cast<int>(length_px / min_gap_px), 1, 10);
      return ticks_inside(lo, hi, nice_ticks(lo, hi, max_intervals).step);
    }

    vtkSmartPointer<vtkTextActor>
    text_at(const std::string &text,
            double             x,
            double             y,
            int                font,
            int                horizontal, // -1 left, 0 centre, 1 right
            int                vertical)                  // -1 bottom, 0 centre, 1 top
    {
      auto actor = vtkSmartPointer<vtkTextActor>::New();
      actor->SetInput(text.c_str());
      style_text(actor->GetTextProperty(), font);
      vtkTextProperty *p = actor->GetTextProperty();
      if (horizontal < 0)
        p->SetJustificationToLeft();
      else if (horizontal == 0)
        p->SetJustificationToCentered();
      else
        p->SetJustificationToRight();
      if (vertical < 0)
        p->SetVerticalJustificationToBottom();
      else if (vertical == 0)
        p->SetVerticalJustificationToCentered();
      else
        p->SetVerticalJustificationToTop();
      actor->SetPosition(x, y);
      return actor;
    }

    // Width in pixels of text in DejaVu Sans (an estimate: 0.62 em per
    // character, as bar_labels assumes).
    double
    text_px(const std::string &text, double font)
    {
      return 0.62 * text.size() * font;
    }

    // Pixels of the frame and ticks of 2D axes around the model viewport.
    struct AxesLayout
    {
      int left = 0, right = 0, bottom = 0, top = 0;
    };

    AxesLayout
    axes_layout(const double bounds[6], int font)
    {
      // The widest y label of a tick step fitted to the model's height.
      const double tick_font = 0.8 * font;
      const auto   ticks =
        axis_ticks(bounds[2], bounds[3], 600.0, 2.5 * tick_font);
      const int d =
        decimals_for_step(ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0);
      double widest = 0.0;
      for (double v : ticks)
        widest = std::max(widest, text_px(fixed(v, d), tick_font));
      AxesLayout l;
      l.left   = static_cast<int>(widest + 3.2 * font);
      l.right  = static_cast<int>(1.8 * font);
      l.bottom = static_cast<int>(3.6 * font);
      l.top    = static_cast<int>(0.8 * font);
      return l;
    }

    // The frame of the viewport box (pixels x0 x1 y0 y1 of the window), with
    // ticks and labels at round values of the world window wx0..wx1,
    // wy0..wy1, and the axis titles "x [m]" and "y [m]".
    void
    draw_axes(vtkRenderer *overlay,
              const double box[4],
              const double window[4],
              int          font)
    {
      const double         tick_font = 0.8 * font;
      const double         tick_len  = 0.45 * font;
      vtkNew<vtkPoints>    points;
      vtkNew<vtkCellArray> lines;
      auto line = [&](double x0, double y0, double x1, double y1) {
        const vtkIdType a      = points->InsertNextPoint(x0, y0, 0.0);
        const vtkIdType b      = points->InsertNextPoint(x1, y1, 0.0);
        const vtkIdType ids[2] = {a, b};
        lines->InsertNextCell(2, ids);
      };
      line(box[0], box[2], box[1], box[2]);
      line(box[1], box[2], box[1], box[3]);
      line(box[1], box[3], box[0], box[3]);
      line(box[0], box[3], box[0], box[2]);

      for (int axis = 0; axis < 2; ++axis)
        {
          const double lo = window[2 * axis], hi = window[2 * axis + 1];
          const double p0 = box[2 * axis], p1 = box[2 * axis + 1];
          const double min_gap =
            axis == 0 ? text_px(fixed(std::max(std::abs(lo), std::abs(hi)), 3),
                                tick_font) +
                          1.5 * font :
                        2.5 * tick_font;
          const auto ticks = axis_ticks(lo, hi, p1 - p0, min_gap);
          const int  d =
            decimals_for_step(ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0);
          for (double v : ticks)
            {
              const double p = p0 + (v - lo) / (hi - lo) * (p1 - p0);
              if (axis == 0)
                {
                  line(p, box[2], p, box[2] - tick_len);
                  overlay->AddActor2D(text_at(fixed(v, d),
                                              p,
                                              box[2] - 1.6 * tick_len,
                                              static_cast<int>(tick_font),
                                              0,
                                              1));
                }
              else
                {
                  line(box[0], p, box[0] - tick_len, p);
                  overlay->AddActor2D(text_at(fixed(v, d),
                                              box[0] - 1.6 * tick_len,
                                              p,
                                              static_cast<int>(tick_font),
                                              1,
                                              0));
                }
            }
        }
      overlay->AddActor2D(text_at("x [m]",
                                  (box[0] + box[1]) / 2,
                                  box[2] - 1.6 * tick_len - 1.25 * tick_font,
                                  font,
                                  0,
                                  1));
      auto y_title =
        text_at("y [m]", 0.2 * font, (box[2] + box[3]) / 2, font, 0, 1);
      y_title->GetTextProperty()->SetOrientation(90.0);
      overlay->AddActor2D(y_title);

      vtkNew<vtkPolyData> frame;
      frame->SetPoints(points);
      frame->SetLines(lines);
      vtkNew<vtkPolyDataMapper2D> mapper;
      mapper->SetInputData(frame);
      vtkNew<vtkActor2D> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
      actor->GetProperty()->SetLineWidth(std::max(1.0, font / 14.0));
      overlay->AddActor2D(actor);
    }

    // x, y, z arrows in a corner renderer that looks from where `camera`
    // looks.
    void
    draw_triad(vtkRenderWindow *window,
               vtkCamera       *camera,
               const double     viewport[4],
               int              font)
    {
      vtkNew<vtkRenderer> corner;
      corner->SetLayer(1);
      corner->InteractiveOff();
      corner->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
      vtkNew<vtkAxesActor> triad;
      triad->SetShaftTypeToCylinder();
      triad->SetTotalLength(1.0, 1.0, 1.0);
      triad->SetCylinderRadius(0.03);
      triad->SetConeRadius(0.35);
      for (vtkCaptionActor2D *c : {triad->GetXAxisCaptionActor2D(),
                                   triad->GetYAxisCaptionActor2D(),
                                   triad->GetZAxisCaptionActor2D()})
        {
          c->GetTextActor()->SetTextScaleModeToNone();
          style_text(c->GetCaptionTextProperty(), font, true);
        }
      corner->AddActor(triad);
      double direction[3];
      camera->GetDirectionOfProjection(direction);
      vtkCamera *c = corner->GetActiveCamera();
      c->SetFocalPoint(0.4, 0.4, 0.4);
      c->SetPosition(0.4 - 10 * direction[0],
                     0.4 - 10 * direction[1],
                     0.4 - 10 * direction[2]);
      c->SetViewUp(camera->GetViewUp());
      c->ParallelProjectionOn();
      c->SetParallelScale(1.0);
      corner->ResetCameraClippingRange();
      window->AddRenderer(corner);
    }

    // Lines drawn on top of the model, black with a white halo so that they
    // show on dark and light colours alike; in 2D lifted towards the viewer.
    void
    draw_outline(vtkRenderer *model, vtkPolyData *lines, double lift, int font)
    {
      const double width = std::max(2.0, font / 9.0);
      for (int pass = 0; pass < 2; ++pass)
        {
          vtkNew<vtkPolyDataMapper> mapper;
          mapper->SetInputData(lines);
          mapper->ScalarVisibilityOff();
          vtkNew<vtkActor> actor;
          actor->SetMapper(mapper);
          const double grey = pass == 0 ? 1.0 : 0.0;
          actor->GetProperty()->SetColor(grey, grey, grey);
          actor->GetProperty()->SetLineWidth(pass == 0 ? width + 3.0 : width);
          actor->GetProperty()->SetLighting(false);
          actor->SetPosition(0., 0., (1.0 + pass) * lift);
          model->AddActor(actor);
        }
    }
  } // namespace

  std::array<int, 2>
  draw_field_picture(const FieldPicture &p, const std::string &out)
  {
    double bounds[6];
    p.model->GetBounds(bounds);
    const bool is_2d  = is_flat(p.model);
    const bool render = !p.caption.empty() || p.axes; // pdfem-render's layout
    int        width = p.width, height = p.height;

    // Layout (pixels): title band on top, colour bar band at the bottom, the
    // model in between (pdfem-render: framed by axes). With auto_height, a 2D
    // model gets a picture as high as its shape needs.
    const int  font    = std::clamp(static_cast<int>(std::lround(
                                  std::sqrt(1.0 * width * height) / 45.0)),
                                12,
                                72);
    const bool axes_2d = p.axes && is_2d;
    const int  bar_px  = static_cast<int>(5.6 * font);
    AxesLayout margins;
    if (axes_2d)
      margins = axes_layout(bounds, font);
    double model_px = 0.0;
    if (is_2d && p.auto_height)
      {
        const double w =
          p.zoom ? (*p.zoom)[1] - (*p.zoom)[0] : bounds[1] - bounds[0];
        const double h =
          p.zoom ? (*p.zoom)[3] - (*p.zoom)[2] : bounds[3] - bounds[2];
        const double inner = width - margins.left - margins.right;
        model_px           = h > 0 && w > 0 ? inner * h / w * 1.04 : inner;
        if (render && model_px > 0.75 * width)
          {
            // A tall model: a narrower picture instead of white margins.
            const int narrower =
              static_cast<int>(std::max(0.75 * width * w / (h * 1.04) +
                                          margins.left + margins.right,
                                        0.5 * width));
            model_px =
              std::min((narrower - margins.left - margins.right) * h / w * 1.04,
                       0.75 * width);
            width = narrower;
          }
        model_px = std::clamp(model_px, 0.3 * p.width, 0.8 * p.width);
      }
    // The caption's parts, joined into lines that fit the width.
    const int                caption_font = static_cast<int>(0.8 * font);
    std::vector<std::string> caption_lines;
    for (const std::string &part : p.caption)
      {
        const std::string longer =
          caption_lines.empty() ? part :
                                  caption_lines.back() + "   \u00b7   " + part;
        if (!caption_lines.empty() &&
            text_px(longer, 0.92 * caption_font) <= 0.96 * width)
          caption_lines.back() = longer;
        else
          caption_lines.push_back(part);
      }
    int title_px = p.title.empty() ? 0 : static_cast<int>(2.4 * font);
    if (render)
      title_px = static_cast<int>((p.title.empty() ? 0.4 : 2.2) * font +
                                  1.3 * font *
                                    static_cast<double>(caption_lines.size()) +
                                  (caption_lines.empty() ? 0.0 : 0.2 * font));
    if (is_2d && p.auto_height)
      height = static_cast<int>(model_px) + title_px + bar_px + margins.bottom +
               margins.top;
    const double title_frac = static_cast<double>(title_px) / height;
    const double bar_frac   = static_cast<double>(bar_px) / height;
    // The model's viewport (x0, y0, x1, y1, normalised).
    const double viewport[4] = {
      static_cast<double>(margins.left) / width,
      static_cast<double>(bar_px + margins.bottom) / height,
      1.0 - static_cast<double>(margins.right) / width,
      1.0 - static_cast<double>(title_px + margins.top) / height};

    vtkNew<vtkRenderWindow> window;
    require_display(window);
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    // Multisampling smooths curved boundaries, but with --edges it leaves faint
    // seams along the diagonals of quadrilaterals (they are drawn as two
    // triangles): off in that case.
    window->SetMultiSamples(p.edges ? 0 : 8);
    vtkNew<vtkRenderer> background; // white behind the margins of the axes
    if (render)
      {
        window->SetNumberOfLayers(2);
        background->SetBackground(1.0, 1.0, 1.0);
        background->InteractiveOff();
        window->AddRenderer(background);
      }

    auto lut = make_lookup_table(p.colormap, p.lo, p.hi);

    // The model.
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputData(p.model);
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn();
    if (p.scalar.on_points)
      mapper->SetScalarModeToUsePointFieldData();
    else
      mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(p.scalar.name.c_str());
    mapper->ScalarVisibilityOn();
    if (p.outline != nullptr && !is_2d)
      mapper->SetResolveCoincidentTopologyToPolygonOffset();

    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    if (is_2d)
      {
        // Flat colours: exactly those of the colour bar.
        actor->GetProperty()->SetAmbient(1.0);
        actor->GetProperty()->SetDiffuse(0.0);
        actor->GetProperty()->SetSpecular(0.0);
      }
    else
      {
        actor->GetProperty()->SetAmbient(0.3);
        actor->GetProperty()->SetDiffuse(0.8);
        actor->GetProperty()->SetSpecular(0.0);
      }
    if (p.edges)
      {
        actor->GetProperty()->EdgeVisibilityOn();
        actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
        actor->GetProperty()->SetLineWidth(1.0);
      }

    vtkNew<vtkRenderer> model;
    model->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    model->SetBackground(1.0, 1.0, 1.0);
    model->AddActor(actor);
    if (!p.lines_file.empty())
      {
        // Polylines on top (crack paths): lifted a little towards the
        // viewer so that they are not hidden in the model's plane.
        if (!std::filesystem::exists(p.lines_file))
          throw UsageError("--lines: the file " + in_quotes(p.lines_file) +
                           " does not exist");
        vtkNew<vtkPolyDataReader> lines_reader;
        lines_reader->SetFileName(p.lines_file.c_str());
        lines_reader->Update();
        vtkNew<vtkPolyDataMapper> lines_mapper;
        lines_mapper->SetInputConnection(lines_reader->GetOutputPort());
        lines_mapper->ScalarVisibilityOff();
        vtkNew<vtkActor> lines_actor;
        lines_actor->SetMapper(lines_mapper);
        lines_actor->GetProperty()->SetColor(0., 0., 0.);
        lines_actor->GetProperty()->SetLineWidth(3.0);
        if (is_2d)
          lines_actor->SetPosition(0., 0., 1e-3 * (bounds[1] - bounds[0]));
        model->AddActor(lines_actor);
      }
    if (p.outline != nullptr)
      draw_outline(model,
                   p.outline,
                   is_2d ? 1e-3 * std::max(bounds[1] - bounds[0],
                                           bounds[3] - bounds[2]) :
                           0.0,
                   font);
    window->AddRenderer(model);
    vtkNew<vtkLight> head_light, key_light;
    if (!is_2d)
      {
        // In an isometric view the three visible faces of a box are equally
        // inclined to the view direction, so a headlight alone shades them
        // alike: add a key light from the upper left.
        model->AutomaticLightCreationOff();
        head_light->SetLightTypeToCameraLight();
        head_light->SetPosition(0.0, 0.0, 1.0);
        head_light->SetFocalPoint(0.0, 0.0, 0.0);
        head_light->SetIntensity(0.7);
        key_light->SetLightTypeToCameraLight();
        key_light->SetPosition(-0.5, 1.0, 0.5);
        key_light->SetFocalPoint(0.0, 0.0, 0.0);
        key_light->SetIntensity(0.5);
        model->AddLight(head_light);
        model->AddLight(key_light);
      }

    const double model_aspect =
      width * (viewport[2] - viewport[0]) /
      std::max(1.0,
               render ? height * (viewport[3] - viewport[1]) :
                        height * (1.0 - bar_frac - title_frac));
    vtkCamera *camera = model->GetActiveCamera();
    if (is_2d)
      {
        if (p.zoom)
          {
            const double box[6] = {(*p.zoom)[0],
                                   (*p.zoom)[1],
                                   (*p.zoom)[2],
                                   (*p.zoom)[3],
                                   bounds[4],
                                   bounds[5]};
            fit_camera(camera, box, {0, 0, 1}, {0, 1, 0}, model_aspect, 1.0);
          }
        else
          fit_camera(camera, bounds, {0, 0, 1}, {0, 1, 0}, model_aspect, 1.04);
      }
    else
      fit_camera(camera, bounds, {1, 1, 1}, {0, 0, 1}, model_aspect, 1.06);
    model->ResetCameraClippingRange();

    if (render)
      {
        // pdfem-render: axes (2D) or a triad (3D) in an overlay.
        vtkNew<vtkRenderer> overlay;
        overlay->SetLayer(1);
        overlay->InteractiveOff();
        if (axes_2d)
          {
            const double  box[4]   = {viewport[0] * width,
                                      viewport[2] * width,
                                      viewport[1] * height,
                                      viewport[3] * height};
            const double *focal    = camera->GetFocalPoint();
            const double  half_h   = camera->GetParallelScale();
            const double  half_w   = half_h * model_aspect;
            const double  world[4] = {focal[0] - half_w,
                                      focal[0] + half_w,
                                      focal[1] - half_h,
                                      focal[1] + half_h};
            draw_axes(overlay, box, world, font);
          }
        window->AddRenderer(overlay);
        if (p.axes && !is_2d)
          {
            const double size      = 0.16 * std::min(width, height);
            const double corner[4] = {viewport[0],
                                      viewport[1],
                                      viewport[0] + size / width,
                                      viewport[1] + size / height};
            draw_triad(window, camera, corner, static_cast<int>(0.8 * font));
          }
      }

    // The colour bar, horizontal, in its own band: its title above, the numbers
    // below.
    vtkNew<vtkRenderer> bar_renderer;
    bar_renderer->SetViewport(0.0, 0.0, 1.0, bar_frac);
    bar_renderer->SetBackground(1.0, 1.0, 1.0);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetOrientationToHorizontal();
    vtkNew<vtkDoubleArray>    bar_values;
    const std::vector<double> labels =
      bar_labels(p.lo, p.hi, 0.7 * width, 0.85 * font, p.bar_end_labels);
    for (double v : labels)
      bar_values->InsertNextValue(v);
    bar->SetCustomLabels(bar_values);
    bar->SetUseCustomLabels(true);
    if (p.bar_end_labels)
      bar->SetLabelFormat("%.3g");
    else
      {
        double step = p.hi - p.lo;
        for (std::size_t i = 0; i + 1 < labels.size(); ++i)
          step = std::min(step, labels[i + 1] - labels[i]);
        const std::string format =
          "%." + std::to_string(decimals_for_step(step)) + "f";
        bar->SetLabelFormat(format.c_str());
      }
    bar->SetMaximumNumberOfColors(256);
    bar->UnconstrainedFontSizeOn();
    bar->SetTextPositionToPrecedeScalarBar();
    style_text(bar->GetLabelTextProperty(), static_cast<int>(0.85 * font));
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.15, 0.04);
    bar->SetWidth(0.7);
    bar->SetHeight(0.6);
    bar->SetBarRatio(0.45);
    bar_renderer->AddActor2D(bar);
    vtkNew<vtkTextActor> bar_title;
    bar_title->SetInput(p.bar_title.c_str());
    style_text(bar_title->GetTextProperty(), font);
    bar_title->GetTextProperty()->SetJustificationToCentered();
    bar_title->GetTextProperty()->SetVerticalJustificationToCentered();
    bar_title->GetPositionCoordinate()
      ->SetCoordinateSystemToNormalizedViewport();
    bar_title->GetPositionCoordinate()->SetValue(0.5, 0.8);
    bar_renderer->AddActor2D(bar_title);
    vtkNew<vtkTextActor> note;
    if (!p.note.empty())
      {
        note->SetInput(p.note.c_str());
        style_text(note->GetTextProperty(),
                   std::max(10, static_cast<int>(0.75 * font)));
        note->GetTextProperty()->SetColor(0.3, 0.3, 0.3);
        note->GetTextProperty()->SetVerticalJustificationToTop();
        note->SetPosition(0.5 * font, bar_px - 0.4 * font);
        bar_renderer->AddActor2D(note);
      }
    window->AddRenderer(bar_renderer);

    if (title_px > 0)
      {
        vtkNew<vtkRenderer> title_renderer;
        title_renderer->SetViewport(0.0, 1.0 - title_frac, 1.0, 1.0);
        title_renderer->SetBackground(1.0, 1.0, 1.0);
        if (!p.title.empty())
          {
            auto title = vtkSmartPointer<vtkTextActor>::New();
            title->SetInput(p.title.c_str());
            style_text(title->GetTextProperty(),
                       static_cast<int>(1.3 * font),
                       true);
            title->GetTextProperty()->SetJustificationToCentered();
            title->GetTextProperty()->SetVerticalJustificationToCentered();
            title->GetPositionCoordinate()
              ->SetCoordinateSystemToNormalizedViewport();
            title->GetPositionCoordinate()->SetValue(
              0.5, render ? 1.0 - 1.1 * font / title_px : 0.45);
            title_renderer->AddActor2D(title);
          }
        for (std::size_t i = 0; i < caption_lines.size(); ++i)
          {
            // Lines of 1.3 font from the bottom of the band up.
            auto line =
              text_at(caption_lines[i],
                      0.5 * width,
                      (0.85 + 1.3 * (caption_lines.size() - 1 - i)) * font,
                      caption_font,
                      0,
                      0);
            line->GetTextProperty()->SetColor(0.25, 0.25, 0.25);
            title_renderer->AddActor2D(line);
          }
        window->AddRenderer(title_renderer);
      }

    window->Render();
    write_png(window, out);
    return {width, height};
  }
} // namespace pdfem_plot
