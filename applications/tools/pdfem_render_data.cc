// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-render: which dataset of a .pvd, the units of pdfem's arrays, the
// automatic warp factor, crack gaps and the outline of the PD region.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <utility>

#include "pdfem_render.h"
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStripper.h>
#include <vtkThreshold.h>
#include <vtkUnstructuredGrid.h>

namespace pdfem_render
{
  using pdfem_plot::in_quotes;
  using pdfem_plot::RunError;
  using pdfem_plot::UsageError;

  std::vector<Dataset>
  datasets_of(const std::string &file)
  {
    if (!pdfem_plot::ends_with(file, ".pvd"))
      return {{file, std::nullopt}};
    std::ifstream in(file);
    if (!in)
      throw RunError("cannot read " + in_quotes(file));
    std::stringstream text;
    text << in.rdbuf();
    const std::string xml = text.str();
    if (xml.find("<Collection") == std::string::npos)
      throw RunError(in_quotes(file) +
                     " is not a ParaView collection (.pvd): no <Collection>");
    // <DataSet timestep="..." file="..."/>, attributes in any order.
    const std::regex tag(R"(<DataSet\b([^>]*)>)");
    const std::regex attribute(R"((\w+)\s*=\s*(?:"([^"]*)\"|'([^']*)'))");
    const std::filesystem::path folder =
      std::filesystem::path(file).parent_path();
    std::vector<Dataset> datasets;
    for (auto t = std::sregex_iterator(xml.begin(), xml.end(), tag);
         t != std::sregex_iterator();
         ++t)
      {
        const std::string                  attributes = (*t)[1];
        std::map<std::string, std::string> values;
        for (auto a = std::sregex_iterator(attributes.begin(),
                                           attributes.end(),
                                           attribute);
             a != std::sregex_iterator();
             ++a)
          values[(*a)[1]] = (*a)[2].matched ? (*a)[2] : (*a)[3];
        if (values.count("file") == 0 || values["file"].empty())
          throw RunError(in_quotes(file) + ": dataset " +
                         std::to_string(datasets.size()) +
                         " has no file attribute");
        Dataset                     d;
        const std::filesystem::path path(values["file"]);
        d.file = (path.is_absolute() ? path : folder / path).string();
        double time;
        if (values.count("timestep") != 0 &&
            pdfem_plot::parse_number(values["timestep"], time))
          d.time = time;
        datasets.push_back(d);
      }
    if (datasets.empty())
      throw RunError(in_quotes(file) + " lists no dataset");
    return datasets;
  }

  std::size_t
  pick_step(const std::string &text, std::size_t count, const std::string &file)
  {
    const long n       = static_cast<long>(count);
    const auto allowed = "0.." + std::to_string(n - 1) + ", or -" +
                         std::to_string(n) + "..-1 counted from the end";
    const auto what = in_quotes(file) + " has " + std::to_string(n) +
                      (n == 1 ? " dataset" : " datasets");
    double v;
    if (!pdfem_plot::parse_number(text, v) || v != std::floor(v) ||
        std::abs(v) > 1e15)
      throw UsageError("--step needs an integer (" + allowed + "; " + what +
                       "), got " + in_quotes(text));
    const long k = static_cast<long>(v);
    if (k >= n || k < -n)
      throw UsageError("--step " + text + " is out of range: " + what +
                       " (allowed: " + allowed + ")");
    return static_cast<std::size_t>(k < 0 ? n + k : k);
  }

  Unit
  unit_of(const std::string &field, double largest)
  {
    auto starts = [&](const std::string &p) { return field.rfind(p, 0) == 0; };
    auto ends   = [&](const std::string &s) {
      return field.size() >= s.size() &&
             field.compare(field.size() - s.size(), s.size(), s) == 0;
    };
    Unit u;
    if (field == "displacement")
      u.base = "m";
    else if (starts("stress_") || ends("_stress"))
      u.base = "Pa";
    else if (field == "damage" || field == "pd_region" ||
             field == "node_kind" || field == "material_id" ||
             field == "rank" || field == "cracked")
      u.base = "-";
    u.symbol = u.base;
    // Prefixes: the largest of them that leaves `largest` at 1 or more.
    std::vector<std::pair<std::string, double>> prefixes;
    if (u.base == "Pa")
      prefixes = {{"G", 1e9}, {"M", 1e6}, {"k", 1e3}, {"", 1.0}};
    else if (u.base == "m")
      prefixes = {{"", 1.0}, {"m", 1e-3}, {"\u00b5", 1e-6}, {"n", 1e-9}};
    if (!prefixes.empty() && largest > 0 && std::isfinite(largest))
      {
        auto chosen = prefixes.back();
        for (const auto &p : prefixes)
          if (largest >= p.second)
            {
              chosen = p;
              break;
            }
        u.symbol = chosen.first + u.base;
        u.factor = 1.0 / chosen.second;
      }
    return u;
  }

  std::string
  with_unit(const std::string &label, const Unit &unit)
  {
    return unit.symbol.empty() ? label : label + " [" + unit.symbol + "]";
  }

  AutoWarp
  auto_warp(vtkUnstructuredGrid *grid)
  {
    AutoWarp      w;
    vtkDataArray *u = grid->GetPointData()->GetArray("displacement");
    double        bounds[6];
    grid->GetBounds(bounds);
    w.model_size = std::max(
      {bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]});
    if (u == nullptr || u->GetNumberOfComponents() < 2 ||
        u->GetNumberOfComponents() > 3)
      return w;
    w.has_displacement = true;
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
      {
        double m = 0.0;
        for (int c = 0; c < u->GetNumberOfComponents(); ++c)
          m += u->GetComponent(i, c) * u->GetComponent(i, c);
        if (std::isfinite(m))
          w.largest = std::max(w.largest, std::sqrt(m));
      }
    if (!(w.largest > 0.0) || !(w.model_size > 0.0))
      return w;
    // The largest round factor that keeps the largest displacement within
    // 10 % of the model size; the steps 1, 2, 2.5, 5, 10 are at most a factor
    // 2 apart, so it is at least 5 %. Never below 1 (true scale).
    const double limit = 0.10 * w.model_size / w.largest;
    w.factor           = 1.0;
    if (limit > 1.0)
      {
        const double power = std::pow(10.0, std::floor(std::log10(limit)));
        for (double f : {5.0, 2.5, 2.0, 1.0})
          if (f * power <= limit * (1 + 1e-12))
            {
              w.factor = f * power;
              break;
            }
      }
    return w;
  }

  vtkSmartPointer<vtkPointSet>
  without_cracked_cells(vtkPointSet *model, long &n_cracked)
  {
    vtkDataArray *cracked = model->GetCellData()->GetArray("cracked");
    if (cracked == nullptr)
      {
        n_cracked = -1;
        return model;
      }
    n_cracked = 0;
    for (vtkIdType i = 0; i < cracked->GetNumberOfTuples(); ++i)
      n_cracked += cracked->GetComponent(i, 0) > 0.5 ? 1 : 0;
    if (n_cracked == 0)
      return model;
    vtkNew<vtkThreshold> keep;
    keep->SetInputData(model);
    keep->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "cracked");
    keep->SetThresholdFunction(vtkThreshold::THRESHOLD_LOWER);
    keep->SetLowerThreshold(0.5);
    keep->Update();
    vtkSmartPointer<vtkPointSet> kept =
      vtkPointSet::SafeDownCast(keep->GetOutputDataObject(0));
    return kept;
  }

  vtkSmartPointer<vtkPolyData>
  pd_outline(vtkPointSet *model, bool is_2d, long &n_pd_cells)
  {
    n_pd_cells = -1;
    if (model->GetCellData()->GetArray("pd_region") == nullptr)
      return nullptr;
    // In 2D the cells themselves; in 3D the faces of the model's surface,
    // which carry the arrays of their cells.
    vtkSmartPointer<vtkDataSet> faces = model;
    if (!is_2d)
      {
        vtkNew<vtkDataSetSurfaceFilter> surface;
        surface->SetInputData(model);
        surface->Update();
        faces = surface->GetOutput();
      }
    vtkDataArray *pd      = faces->GetCellData()->GetArray("pd_region");
    vtkDataArray *cracked = faces->GetCellData()->GetArray("cracked");
    if (pd == nullptr)
      return nullptr;
    // Edges of PD faces that only one PD face has: the region's boundary.
    std::map<std::pair<vtkIdType, vtkIdType>, std::pair<int, vtkIdType>> edges;
    vtkNew<vtkGenericCell>                                               cell;
    long n_pd = 0;
    for (vtkIdType c = 0; c < faces->GetNumberOfCells(); ++c)
      {
        if (pd->GetComponent(c, 0) < 0.5)
          continue;
        ++n_pd;
        faces->GetCell(c, cell);
        for (int e = 0; e < cell->GetNumberOfEdges(); ++e)
          {
            vtkCell  *edge = cell->GetEdge(e);
            vtkIdType a = edge->GetPointId(0), b = edge->GetPointId(1);
            auto     &entry = edges[{std::min(a, b), std::max(a, b)}];
            ++entry.first;
            entry.second = c;
          }
      }
    n_pd_cells = is_2d ? n_pd : 0;
    if (!is_2d)
      {
        vtkDataArray *cells_pd = model->GetCellData()->GetArray("pd_region");
        n_pd_cells             = 0;
        for (vtkIdType c = 0; c < cells_pd->GetNumberOfTuples(); ++c)
          n_pd_cells += cells_pd->GetComponent(c, 0) > 0.5 ? 1 : 0;
      }
    vtkNew<vtkCellArray> lines;
    for (const auto &[ends, use] : edges)
      if (use.first == 1 &&
          (cracked == nullptr || cracked->GetComponent(use.second, 0) < 0.5))
        {
          const vtkIdType ids[2] = {ends.first, ends.second};
          lines->InsertNextCell(2, ids);
        }
    vtkNew<vtkPolyData> edges_only;
    edges_only->SetPoints(vtkPointSet::SafeDownCast(faces)->GetPoints());
    edges_only->SetLines(lines);
    // Joined into polylines, so that the lines have clean corners.
    vtkNew<vtkStripper> join;
    join->SetInputData(edges_only);
    join->JoinContiguousSegmentsOn();
    join->Update();
    vtkSmartPointer<vtkPolyData> outline = join->GetOutput();
    return outline;
  }

  std::string
  plain_number(double v)
  {
    char text[64];
    if (!std::isfinite(v) || v == 0.0 || std::abs(v) >= 1e15 ||
        std::abs(v) < 1e-9)
      std::snprintf(text, sizeof(text), "%g", v);
    else if (v == std::floor(v))
      std::snprintf(text, sizeof(text), "%.0f", v);
    else
      return fixed_trimmed(v,
                           std::clamp(3 - static_cast<int>(std::floor(
                                            std::log10(std::abs(v)))),
                                      0,
                                      12));
    return text;
  }

  std::string
  fixed_trimmed(const double v, const int decimals)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", decimals, v);
    std::string s = text;
    if (s.find('.') != std::string::npos)
      {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.')
          s.pop_back();
      }
    return s;
  }
} // namespace pdfem_render
