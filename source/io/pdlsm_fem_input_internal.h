// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the io module: the token helpers shared by the readers of the
// PDLSM-FEM command file (pdlsm_fem_input.cc) and mesh file
// (pdlsm_fem_mesh_input.cc).
#ifndef PDFEM_SOURCE_IO_PDLSM_FEM_INPUT_INTERNAL_H
#define PDFEM_SOURCE_IO_PDLSM_FEM_INPUT_INTERNAL_H

#include <string>
#include <string_view>

namespace pdfem
{
  namespace IO
  {
    namespace internal
    {
      /// "line <line>", the parameter of an InputError.
      std::string
      at_line(unsigned int line);

      /// A token as it appears in a message (long separator lines shortened).
      std::string
      in_quotes(std::string_view token);

      inline bool
      is_blank(const char c)
      {
        return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
      }

      /// @p token as a finite number, or false.
      bool
      to_double(std::string_view token, double &value);

      /// @p token as a whole number, or false.
      bool
      to_integer(std::string_view token, long long &value);

      /// The whole of @p file, or false if it is not a readable file.
      bool
      read_text(const std::string &file, std::string &text);
    } // namespace internal
  }   // namespace IO
} // namespace pdfem

#endif
