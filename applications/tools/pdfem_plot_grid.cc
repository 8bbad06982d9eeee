// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot and pdfem-render: the data side of field pictures (reading a
// .vtu/.pvtu file, the array to colour by, the deformed shape).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "pdfem_plot.h"
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkSmartPointer.h>
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
  } // namespace

  vtkSmartPointer<vtkUnstructuredGrid>
  read_grid(const std::string &file)
  {
    vtkSmartPointer<vtkXMLReader> reader;
    if (ends_with(file, ".pvtu"))
      reader = vtkSmartPointer<vtkXMLPUnstructuredGridReader>::New();
    else
      reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    // Catch VTK's own error output, so that a bad file gives one clear line.
    vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
    vtkNew<CapturingOutputWindow>    capture;
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

  FieldScalar
  add_field_scalar(vtkUnstructuredGrid *grid,
                   const std::string   &field,
                   const Arguments     &a,
                   const std::string   &file)
  {
    // Find the array: point data first, then cell data.
    FieldScalar   s;
    vtkDataArray *array = grid->GetPointData()->GetArray(field.c_str());
    if (array == nullptr)
      {
        array       = grid->GetCellData()->GetArray(field.c_str());
        s.on_points = false;
      }
    if (array == nullptr)
      throw UsageError(
        "--field " + in_quotes(field) + " is not in " + in_quotes(file) +
        "; point arrays: " + describe_arrays(grid->GetPointData()) +
        "; cell arrays: " + describe_arrays(grid->GetCellData()));

    const int n_components = array->GetNumberOfComponents();
    s.component            = -1; // magnitude
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
        s.component = static_cast<int>(k);
      }
    else if (n_components == 1)
      s.component = 0;

    s.label = field;
    if (n_components > 1)
      {
        if (s.component < 0)
          s.label = field + " magnitude";
        else if (n_components <= 3)
          s.label = field + " (" + std::string(1, "xyz"[s.component]) + ")";
        else
          s.label = field + " [" + std::to_string(s.component) + "]";
      }

    // The scalar to colour by, as its own array (so that the colour range is
    // easy to get right).
    vtkNew<vtkDoubleArray> scalar;
    scalar->SetName(s.name.c_str());
    scalar->SetNumberOfTuples(array->GetNumberOfTuples());
    s.lo = std::numeric_limits<double>::max();
    s.hi = -s.lo;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      {
        double v = 0.0;
        if (s.component >= 0)
          v = array->GetComponent(i, s.component);
        else
          {
            for (int c = 0; c < n_components; ++c)
              v += array->GetComponent(i, c) * array->GetComponent(i, c);
            v = std::sqrt(v);
          }
        scalar->SetValue(i, v);
        if (std::isfinite(v))
          {
            s.lo = std::min(s.lo, v);
            s.hi = std::max(s.hi, v);
          }
      }
    if (s.lo > s.hi)
      throw RunError(in_quotes(field) + " in " + in_quotes(file) +
                     " has no finite values");
    if (s.on_points)
      grid->GetPointData()->AddArray(scalar);
    else
      grid->GetCellData()->AddArray(scalar);
    return s;
  }

  void
  scale_field_scalar(vtkUnstructuredGrid *grid, FieldScalar &s, double factor)
  {
    vtkDataArray *array =
      (s.on_points ? static_cast<vtkFieldData *>(grid->GetPointData()) :
                     static_cast<vtkFieldData *>(grid->GetCellData()))
        ->GetArray(s.name.c_str());
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      array->SetComponent(i, 0, array->GetComponent(i, 0) * factor);
    s.lo *= factor;
    s.hi *= factor;
    if (s.lo > s.hi)
      std::swap(s.lo, s.hi);
  }

  vtkDataArray *
  displacement_array(vtkUnstructuredGrid *grid,
                     const std::string   &option,
                     const std::string   &file)
  {
    vtkDataArray *u = grid->GetPointData()->GetArray("displacement");
    if (u == nullptr || u->GetNumberOfComponents() < 2 ||
        u->GetNumberOfComponents() > 3)
      throw UsageError(
        option +
        " needs a point array 'displacement' with 2 or 3 components; " +
        in_quotes(file) +
        " has point arrays: " + describe_arrays(grid->GetPointData()));
    return u;
  }

  vtkSmartPointer<vtkPointSet>
  warp_by_displacement(vtkUnstructuredGrid *grid,
                       double               factor,
                       const std::string   &option,
                       const std::string   &file)
  {
    vtkDataArray          *u = displacement_array(grid, option, file);
    vtkNew<vtkDoubleArray> u3; // vtkWarpVector wants 3 components
    u3->SetName("pdfem_plot_displacement");
    u3->SetNumberOfComponents(3);
    u3->SetNumberOfTuples(u->GetNumberOfTuples());
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c)
        u3->SetComponent(
          i, c, c < u->GetNumberOfComponents() ? u->GetComponent(i, c) : 0.0);
    grid->GetPointData()->AddArray(u3);
    vtkNew<vtkWarpVector> warper;
    warper->SetInputData(grid);
    warper->SetInputArrayToProcess(0,
                                   0,
                                   0,
                                   vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                   "pdfem_plot_displacement");
    warper->SetScaleFactor(factor);
    warper->Update();
    return vtkPointSet::SafeDownCast(warper->GetOutputDataObject(0));
  }

  bool
  is_flat(vtkDataSet *data)
  {
    double bounds[6];
    data->GetBounds(bounds);
    const double extent_xy =
      std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]);
    return bounds[5] - bounds[4] <= 1e-9 * std::max(extent_xy, 1e-300);
  }
} // namespace pdfem_plot
