// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot field: an unstructured grid (.vtu/.pvtu) coloured by one array,
// as a PNG.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

#include "pdfem_plot.h"
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkLight.h>
#include <vtkLogger.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataReader.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWarpVector.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLReader.h>
#include <vtkXMLUnstructuredGridReader.h>

namespace pdfem_plot
{
  namespace
  {
    // Collects what VTK reports (instead of printing it) while it is the active
    // output window.
    class CapturingOutputWindow : public vtkOutputWindow
    {
    public:
      static CapturingOutputWindow *
      New()
      {
        auto *window = new CapturingOutputWindow;
        window->InitializeObjectBase();
        return window;
      }
      void
      DisplayText(const char *text) override
      {
        keep(text);
      }
      void
      DisplayErrorText(const char *text) override
      {
        keep(text);
      }
      void
      DisplayWarningText(const char *text) override
      {
        keep(text);
      }
      void
      DisplayGenericWarningText(const char *text) override
      {
        keep(text);
      }
      void
      DisplayDebugText(const char *) override
      {}

      // The first message, reduced to its text: VTK's messages read
      // "ERROR: In FILE, line N\nvtkClass (0x...): text"; pipeline failures
      // that only repeat an earlier error are skipped.
      std::string
      first_message() const
      {
        for (const auto &m : messages)
          {
            std::string line;
            for (const auto &l : split(m, '\n'))
              if (!trim(l).empty() && l.rfind("ERROR: In ", 0) != 0 &&
                  l.rfind("Warning: In ", 0) != 0)
                {
                  line = trim(l);
                  break;
                }
            if (line.empty() ||
                line.find("returned failure for request") != std::string::npos)
              continue;
            if (const auto colon = line.find("): ");
                line.rfind("vtk", 0) == 0 && colon != std::string::npos)
              line = line.substr(colon + 3);
            return line;
          }
        return "";
      }
      std::vector<std::string> messages;

    private:
      void
      keep(const char *text)
      {
        if (text != nullptr)
          messages.emplace_back(text);
      }
    };

    vtkSmartPointer<vtkUnstructuredGrid>
    read_grid(const std::string &file)
    {
      vtkSmartPointer<vtkXMLReader> reader;
      if (ends_with(file, ".pvtu"))
        reader = vtkSmartPointer<vtkXMLPUnstructuredGridReader>::New();
      else
        reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
      // Catch VTK's own error output, so that a bad file gives one clear line.
      vtkSmartPointer<vtkOutputWindow> previous =
        vtkOutputWindow::GetInstance();
      vtkNew<CapturingOutputWindow> capture;
      vtkOutputWindow::SetInstance(capture);
      const vtkLogger::Verbosity verbosity =
        vtkLogger::GetCurrentVerbosityCutoff();
      vtkLogger::SetStderrVerbosity(
        vtkLogger::VERBOSITY_OFF); // VTK logs errors there as well
      reader->SetFileName(file.c_str());
      reader->Update();
      vtkLogger::SetStderrVerbosity(verbosity);
      vtkOutputWindow::SetInstance(previous);
      auto *grid =
        vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
      if (!capture->messages.empty() &&
          (grid == nullptr || grid->GetNumberOfPoints() == 0))
        throw RunError("cannot read " + in_quotes(file) + ": " +
                       capture->first_message());
      for (const auto &m :
           capture->messages) // the file was read, but VTK had something to say
        std::cerr << m;
      if (grid == nullptr || grid->GetNumberOfPoints() == 0)
        throw RunError("no points in " + in_quotes(file));
      vtkSmartPointer<vtkUnstructuredGrid> copy =
        vtkSmartPointer<vtkUnstructuredGrid>::New();
      copy->ShallowCopy(grid);
      return copy;
    }

    std::string
    describe_arrays(vtkFieldData *data)
    {
      std::vector<std::string> names;
      for (int i = 0; i < data->GetNumberOfArrays(); ++i)
        if (vtkDataArray *a = data->GetArray(i);
            a != nullptr && a->GetName() != nullptr)
          names.push_back(std::string(a->GetName()) +
                          (a->GetNumberOfComponents() > 1 ?
                             " (" + std::to_string(a->GetNumberOfComponents()) +
                               " components)" :
                             ""));
      return names.empty() ? "none" : join(names);
    }

    std::string
    format_number(double v)
    {
      std::ostringstream s;
      s.precision(4);
      s << v;
      return s.str();
    }
  } // namespace

  int
  run_field(const std::vector<std::string> &args)
  {
    const Arguments a =
      parse_arguments("field",
                      args,
                      {{"--field", "NAME", 1},
                       {"--component", "K", 1},
                       {"--warp", "FACTOR", 1},
                       {"--range", "MIN MAX", 2},
                       {"--colormap", "auto, coolwarm or viridis", 1},
                       {"--title", "TEXT", 1},
                       {"--size", "W H", 2},
                       {"--edges", "", 0},
                       {"--zoom", "X0 X1 Y0 Y1", 4},
                       {"--lines", "FILE.vtk", 1},
                       {"--out", "OUT.png", 1}});
    const std::string file = input_file(a, ".vtu or .pvtu");
    if (!ends_with(file, ".vtu") && !ends_with(file, ".pvtu"))
      throw UsageError("'field' reads .vtu or .pvtu files, got " +
                       in_quotes(file));
    if (!a.has("--field"))
      throw UsageError("'field' needs --field NAME (the array to colour by)");
    const std::string field = a.value("--field");
    const std::string out   = output_file(a);
    int               width = 1000, height = 800;
    if (a.has("--size"))
      {
        const auto size = size_option(a, width, height);
        width           = size[0];
        height          = size[1];
      }
    const std::string colormap = a.value_or("--colormap", "auto");
    if (colormap != "auto" && colormap != "coolwarm" && colormap != "viridis")
      throw UsageError("--colormap must be auto, coolwarm or viridis, got " +
                       in_quotes(colormap));
    double warp = 0.0;
    if (a.has("--warp"))
      warp = number_option(a, "--warp", 0, "a number FACTOR");
    std::array<double, 2> range{};
    if (a.has("--range"))
      {
        range = {number_option(a, "--range", 0, "two numbers MIN MAX"),
                 number_option(a, "--range", 1, "two numbers MIN MAX")};
        if (!(range[0] < range[1]))
          throw UsageError("--range needs MIN < MAX, got " +
                           a.value("--range", 0) + " " + a.value("--range", 1));
      }
    std::array<double, 4> zoom{};
    if (a.has("--zoom"))
      {
        for (std::size_t i = 0; i < 4; ++i)
          zoom[i] = number_option(a, "--zoom", i, "four numbers X0 X1 Y0 Y1");
        if (!(zoom[0] < zoom[1] && zoom[2] < zoom[3]))
          throw UsageError("--zoom needs X0 < X1 and Y0 < Y1, got " +
                           join(a.options.at("--zoom"), " "));
      }
    vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(file);

    // Find the array: point data first, then cell data.
    bool          on_points = true;
    vtkDataArray *array     = grid->GetPointData()->GetArray(field.c_str());
    if (array == nullptr)
      {
        array     = grid->GetCellData()->GetArray(field.c_str());
        on_points = false;
      }
    if (array == nullptr)
      throw UsageError(
        "--field " + in_quotes(field) + " is not in " + in_quotes(file) +
        "; point arrays: " + describe_arrays(grid->GetPointData()) +
        "; cell arrays: " + describe_arrays(grid->GetCellData()));

    const int n_components = array->GetNumberOfComponents();
    int       component    = -1; // -1: magnitude
    if (a.has("--component"))
      {
        std::vector<std::string> allowed;
        for (int c = 0; c < n_components; ++c)
          allowed.push_back(std::to_string(c));
        double k;
        if (!parse_number(a.value("--component"), k) || k != std::floor(k) ||
            k < 0 || k >= n_components)
          throw UsageError(
            "--component for " + in_quotes(field) + " (" +
            std::to_string(n_components) +
            (n_components == 1 ? " component" : " components") + ") must be " +
            (n_components == 1 ? "0" : "one of " + join(allowed)) + ", got " +
            in_quotes(a.value("--component")));
        component = static_cast<int>(k);
      }
    else if (n_components == 1)
      component = 0;

    std::string label = field;
    if (n_components > 1)
      {
        if (component < 0)
          label = field + " magnitude";
        else if (n_components <= 3)
          label = field + " (" + std::string(1, "xyz"[component]) + ")";
        else
          label = field + " [" + std::to_string(component) + "]";
      }

    // The scalar to colour by, as its own array (so that the colour range is
    // easy to get right).
    const std::string      scalar_name = "pdfem_plot_scalar";
    vtkNew<vtkDoubleArray> scalar;
    scalar->SetName(scalar_name.c_str());
    scalar->SetNumberOfTuples(array->GetNumberOfTuples());
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      {
        double v = 0.0;
        if (component >= 0)
          v = array->GetComponent(i, component);
        else
          {
            for (int c = 0; c < n_components; ++c)
              v += array->GetComponent(i, c) * array->GetComponent(i, c);
            v = std::sqrt(v);
          }
        scalar->SetValue(i, v);
        if (std::isfinite(v))
          {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
      }
    if (lo > hi)
      throw RunError(in_quotes(field) + " in " + in_quotes(file) +
                     " has no finite values");
    if (on_points)
      grid->GetPointData()->AddArray(scalar);
    else
      grid->GetCellData()->AddArray(scalar);

    if (a.has("--range"))
      {
        lo = range[0];
        hi = range[1];
      }
    else if (lo == hi)
      {
        const double pad = lo != 0.0 ? 0.01 * std::abs(lo) : 1.0;
        lo -= pad;
        hi += pad;
      }

    // Optionally deform.
    vtkSmartPointer<vtkPointSet> shown = grid;
    if (a.has("--warp"))
      {
        vtkDataArray *u = grid->GetPointData()->GetArray("displacement");
        if (u == nullptr || u->GetNumberOfComponents() < 2 ||
            u->GetNumberOfComponents() > 3)
          throw UsageError(
            "--warp needs a point array 'displacement' with 2 or 3 components; " +
            in_quotes(file) +
            " has point arrays: " + describe_arrays(grid->GetPointData()));
        vtkNew<vtkDoubleArray> u3; // vtkWarpVector wants 3 components
        u3->SetName("pdfem_plot_displacement");
        u3->SetNumberOfComponents(3);
        u3->SetNumberOfTuples(u->GetNumberOfTuples());
        for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
          for (int c = 0; c < 3; ++c)
            u3->SetComponent(i,
                             c,
                             c < u->GetNumberOfComponents() ?
                               u->GetComponent(i, c) :
                               0.0);
        grid->GetPointData()->AddArray(u3);
        vtkNew<vtkWarpVector> warper;
        warper->SetInputData(grid);
        warper->SetInputArrayToProcess(0,
                                       0,
                                       0,
                                       vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                       "pdfem_plot_displacement");
        warper->SetScaleFactor(warp);
        warper->Update();
        shown = vtkPointSet::SafeDownCast(warper->GetOutputDataObject(0));
      }

    double bounds[6];
    shown->GetBounds(bounds);
    const double extent_xy =
      std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]);
    const bool is_2d =
      bounds[5] - bounds[4] <= 1e-9 * std::max(extent_xy, 1e-300);
    if (a.has("--zoom") && !is_2d)
      throw UsageError("--zoom works on 2D models only; " + in_quotes(file) +
                       " is 3D");

    // Layout (pixels): title band on top, colour bar band at the bottom, the
    // model in between. Without --size, a 2D model gets a picture 1000 pixels
    // wide and as high as its shape needs.
    const int font     = std::clamp(static_cast<int>(std::lround(
                                  std::sqrt(1.0 * width * height) / 45.0)),
                                12,
                                72);
    const int title_px = a.has("--title") ? static_cast<int>(2.4 * font) : 0;
    const int bar_px   = static_cast<int>(5.6 * font);
    if (is_2d && !a.has("--size"))
      {
        const double w =
          a.has("--zoom") ? zoom[1] - zoom[0] : bounds[1] - bounds[0];
        const double h =
          a.has("--zoom") ? zoom[3] - zoom[2] : bounds[3] - bounds[2];
        const double model_px = h > 0 && w > 0 ? width * h / w * 1.04 : width;
        height =
          static_cast<int>(std::clamp(model_px, 0.3 * width, 0.8 * width)) +
          title_px + bar_px;
      }
    const double title_frac = static_cast<double>(title_px) / height;
    const double bar_frac   = static_cast<double>(bar_px) / height;

    vtkNew<vtkRenderWindow> window;
    require_display(window);
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    // Multisampling smooths curved boundaries, but with --edges it leaves faint
    // seams along the diagonals of quadrilaterals (they are drawn as two
    // triangles): off in that case.
    window->SetMultiSamples(a.has("--edges") ? 0 : 8);

    auto lut = make_lookup_table(colormap, lo, hi);

    // The model.
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputData(shown);
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn();
    if (on_points)
      mapper->SetScalarModeToUsePointFieldData();
    else
      mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(scalar_name.c_str());
    mapper->ScalarVisibilityOn();

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
    if (a.has("--edges"))
      {
        actor->GetProperty()->EdgeVisibilityOn();
        actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
        actor->GetProperty()->SetLineWidth(1.0);
      }

    vtkNew<vtkRenderer> model;
    model->SetViewport(0.0, bar_frac, 1.0, 1.0 - title_frac);
    model->SetBackground(1.0, 1.0, 1.0);
    model->AddActor(actor);
    if (a.has("--lines"))
      {
        // Polylines on top (crack paths): lifted a little towards the
        // viewer so that they are not hidden in the model's plane.
        const std::string lines_file = a.options.at("--lines")[0];
        if (!std::filesystem::exists(lines_file))
          throw UsageError("--lines: the file " + in_quotes(lines_file) +
                           " does not exist");
        vtkNew<vtkPolyDataReader> lines_reader;
        lines_reader->SetFileName(lines_file.c_str());
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
      width / std::max(1.0, height * (1.0 - bar_frac - title_frac));
    if (is_2d)
      {
        if (a.has("--zoom"))
          {
            const double box[6] = {
              zoom[0], zoom[1], zoom[2], zoom[3], bounds[4], bounds[5]};
            fit_camera(model->GetActiveCamera(),
                       box,
                       {0, 0, 1},
                       {0, 1, 0},
                       model_aspect,
                       1.0);
          }
        else
          fit_camera(model->GetActiveCamera(),
                     bounds,
                     {0, 0, 1},
                     {0, 1, 0},
                     model_aspect,
                     1.04);
      }
    else
      fit_camera(model->GetActiveCamera(),
                 bounds,
                 {1, 1, 1},
                 {0, 0, 1},
                 model_aspect,
                 1.06);
    model->ResetCameraClippingRange();

    // The colour bar, horizontal, in its own band: its title above, the numbers
    // below.
    vtkNew<vtkRenderer> bar_renderer;
    bar_renderer->SetViewport(0.0, 0.0, 1.0, bar_frac);
    bar_renderer->SetBackground(1.0, 1.0, 1.0);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetOrientationToHorizontal();
    vtkNew<vtkDoubleArray> bar_values;
    for (double v : bar_labels(lo, hi, 0.7 * width, 0.85 * font))
      bar_values->InsertNextValue(v);
    bar->SetCustomLabels(bar_values);
    bar->SetUseCustomLabels(true);
    bar->SetLabelFormat("%.3g");
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
    bar_title->SetInput(label.c_str());
    style_text(bar_title->GetTextProperty(), font);
    bar_title->GetTextProperty()->SetJustificationToCentered();
    bar_title->GetTextProperty()->SetVerticalJustificationToCentered();
    bar_title->GetPositionCoordinate()
      ->SetCoordinateSystemToNormalizedViewport();
    bar_title->GetPositionCoordinate()->SetValue(0.5, 0.8);
    bar_renderer->AddActor2D(bar_title);
    vtkNew<vtkTextActor> warp_note;
    if (a.has("--warp"))
      {
        warp_note->SetInput(("displacement x " + format_number(warp)).c_str());
        style_text(warp_note->GetTextProperty(),
                   std::max(10, static_cast<int>(0.75 * font)));
        warp_note->GetTextProperty()->SetColor(0.3, 0.3, 0.3);
        warp_note->GetTextProperty()->SetVerticalJustificationToTop();
        warp_note->SetPosition(0.5 * font, bar_px - 0.4 * font);
        bar_renderer->AddActor2D(warp_note);
      }
    window->AddRenderer(bar_renderer);

    if (a.has("--title"))
      {
        vtkNew<vtkRenderer> title_renderer;
        title_renderer->SetViewport(0.0, 1.0 - title_frac, 1.0, 1.0);
        title_renderer->SetBackground(1.0, 1.0, 1.0);
        vtkNew<vtkTextActor> title;
        title->SetInput(a.value("--title").c_str());
        style_text(title->GetTextProperty(),
                   static_cast<int>(1.3 * font),
                   true);
        title->GetTextProperty()->SetJustificationToCentered();
        title->GetTextProperty()->SetVerticalJustificationToCentered();
        title->GetPositionCoordinate()
          ->SetCoordinateSystemToNormalizedViewport();
        title->GetPositionCoordinate()->SetValue(0.5, 0.45);
        title_renderer->AddActor2D(title);
        window->AddRenderer(title_renderer);
      }

    window->Render();
    write_png(window, out);
    return 0;
  }
} // namespace pdfem_plot
