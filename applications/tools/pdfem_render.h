// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to pdfem-render: the pieces of pdfem_render_data.cc (which dataset
// of a .pvd, units, the automatic warp factor, crack gaps and the outline of
// the PD region), used by pdfem_render.cc.
#ifndef PDFEM_APPLICATIONS_TOOLS_PDFEM_RENDER_H
#define PDFEM_APPLICATIONS_TOOLS_PDFEM_RENDER_H

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pdfem_plot.h"
#include <vtkSmartPointer.h>

class vtkPointSet;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace pdfem_render
{
  /// One dataset of a .pvd collection.
  struct Dataset
  {
    std::string file; ///< path of the .vtu/.pvtu (as it can be opened)
    std::optional<double> time; ///< the DataSet's timestep attribute
  };

  /// The datasets of a .pvd file in the order of the file, or (for a .vtu or
  /// .pvtu) the file itself. RunError if the .pvd cannot be read or holds no
  /// dataset.
  std::vector<Dataset>
  datasets_of(const std::string &file);

  /// The index --step `text` picks among `count` datasets of `file` (0-based;
  /// negative counts from the end). UsageError naming the count otherwise.
  std::size_t
  pick_step(const std::string &text,
            std::size_t        count,
            const std::string &file);

  /// How values of an array are shown: multiplied by factor, in symbol.
  struct Unit
  {
    std::string base; ///< SI unit of pdfem's array: "Pa", "m", "-"; "" unknown
    std::string symbol;       ///< shown unit: "MPa", "mm", "-", ""
    double      factor = 1.0; ///< shown value = factor x stored value
  };

  /// The unit of pdfem's array `field` (displacement [m]; stress_*, *_stress
  /// [Pa]; damage, pd_region, node_kind, material_id, rank, cracked [-]), with
  /// a prefix (k, M, G; m, µ, n) that brings `largest` (the largest magnitude
  /// shown) between 1 and 1000.
  Unit
  unit_of(const std::string &field, double largest);

  /// "stress_xx [MPa]", or the bare label when the unit is unknown.
  std::string
  with_unit(const std::string &label, const Unit &unit);

  /// The automatic warp factor and why.
  struct AutoWarp
  {
    double factor     = 0.0; ///< 0: no displacement to show
    double largest    = 0.0; ///< largest displacement magnitude [m]
    double model_size = 0.0; ///< largest extent of the undeformed model [m]
    bool   has_displacement = false;
  };

  /// A round factor (1, 2, 2.5 or 5 times a power of ten, at least 1) that
  /// makes the largest displacement 5-10 % of the model size.
  AutoWarp
  auto_warp(vtkUnstructuredGrid *grid);

  /// The cells of `model` whose cell array "cracked" is 0 (a crack runs
  /// through the others; leaving them out shows the crack as a gap).
  /// n_cracked: how many were left out; -1 (and model itself) when the array
  /// is absent.
  vtkSmartPointer<vtkPointSet>
  without_cracked_cells(vtkPointSet *model, long &n_cracked);

  /// The boundary of the cells of `model` whose cell array "pd_region" is 1,
  /// as lines (in 3D: where it meets the model's surface), leaving out the
  /// parts along cracked cells. nullptr when there is no such array.
  /// n_pd_cells: the number of PD cells (or -1).
  vtkSmartPointer<vtkPolyData>
  pd_outline(vtkPointSet *model, bool is_2d, long &n_pd_cells);

  /// v without an exponent: integers as such, others with up to 4
  /// significant digits ("2500", "2.5", "0.0125"); %g beyond 1e15 or below
  /// 1e-9.
  std::string
  plain_number(double v);

  /// @p v in fixed notation with @p decimals digits after the point, its
  /// trailing zeros (and a bare point) dropped: 2.500 -> "2.5", 3.0 -> "3".
  std::string
  fixed_trimmed(double v, int decimals);
} // namespace pdfem_render

#endif
