// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_HISTORY_H
#define PDFEM_IO_HISTORY_H

#include <fstream>
#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    /**
     * history.csv: one row per load or time step, columns named once in the
     * header, flushed after every row so that a long run can be watched (and
     * a stopped run keeps what it did). Only the rank that opened it writes.
     */
    class History
    {
    public:
      /// Open @p file and write the header; if !@p active, do nothing at all.
      History(const std::string              &file,
              const std::vector<std::string> &columns,
              bool                            active);

      /**
       * Continue @p file after its first @p rows rows (a restart from a
       * checkpoint taken then): the rows a killed run wrote after it are
       * dropped, and new rows are appended. Throws std::runtime_error if
       * the file's header is not @p columns or it has fewer rows.
       */
      History(const std::string              &file,
              const std::vector<std::string> &columns,
              bool                            active,
              std::size_t                     rows);

      /// The rows written to the file (including those kept on restart).
      std::size_t
      rows() const
      {
        return n_rows;
      }

      /// The name of column @p c.
      const std::string &
      column(std::size_t c) const
      {
        return columns[c];
      }

      /// One row, in the order of the columns. Returns false if it could
      /// not be written (disk full, folder gone).
      bool
      add_row(const std::vector<double> &values);

      /// Turn a set name into a column-name part: "left" stays, a point
      /// "(0, -0.5)" becomes "at_x0_y-0.5".
      static std::string
      column_name(const std::string &name);

    private:
      std::ofstream            out;
      std::size_t              n_columns;
      std::size_t              n_rows = 0;
      std::vector<std::string> columns;
    };
  } // namespace IO
} // namespace pdfem

#endif
