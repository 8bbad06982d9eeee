// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_STATE_ARCHIVE_H
#define PDFEM_BASE_STATE_ARCHIVE_H

#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace pdfem
{
  /**
   * One rank's part of a run's state, as named binary values: what a
   * checkpoint holds (doc/reliability.md, "Checkpoint and restart"). The
   * parts of a run (driver, coupled system, cracks, postprocessors) put
   * their members under names of their own and get them back on restart;
   * values are copied bit for bit, so that a restarted run repeats the
   * uninterrupted one exactly.
   *
   * On disk: a magic line, the entries (name, size, bytes) and an
   * FNV-1a checksum of all of them, so that a truncated or altered file
   * is refused, never half read.
   */
  class StateArchive
  {
  public:
    /// Put a value of a trivially copyable type (numbers, records).
    template <typename T>
    void
    put(const std::string &name, const T &value)
    {
      static_assert(std::is_trivially_copyable_v<T>);
      put_bytes(name, &value, sizeof(T));
    }

    /// Put an array of a trivially copyable type.
    template <typename T>
    void
    put(const std::string &name, const std::vector<T> &values)
    {
      static_assert(std::is_trivially_copyable_v<T>);
      put_bytes(name, values.data(), values.size() * sizeof(T));
    }

    /// Put @p n values starting at @p values (a vector's owned entries).
    void
    put(const std::string &name, const double *values, std::size_t n)
    {
      put_bytes(name, values, n * sizeof(double));
    }

    /// Put this rank's entries of a distributed vector (deal.II's
    /// Trilinos vectors: begin() and locally_owned_size()).
    template <class VectorType>
    void
    put_owned(const std::string &name, const VectorType &v)
    {
      put(name, v.begin(), v.locally_owned_size());
    }

    void
    put(const std::string &name, const std::string &text)
    {
      put_bytes(name, text.data(), text.size());
    }

    /// Is there an entry @p name?
    bool
    has(const std::string &name) const
    {
      return entries.count(name) > 0;
    }

    /// The value @p name (InputError naming the file if missing or of another
    /// size).
    template <typename T>
    T
    get(const std::string &name) const
    {
      static_assert(std::is_trivially_copyable_v<T>);
      T                  value;
      const std::string &bytes = entry(name, sizeof(T));
      std::memcpy(&value, bytes.data(), sizeof(T));
      return value;
    }

    /// The array @p name.
    template <typename T>
    std::vector<T>
    get_vector(const std::string &name) const
    {
      static_assert(std::is_trivially_copyable_v<T>);
      const std::string &bytes = entry(name, 0);
      if (bytes.size() % sizeof(T) != 0)
        wrong_size(name, bytes.size(), sizeof(T));
      std::vector<T> values(bytes.size() / sizeof(T));
      if (!values.empty())
        std::memcpy(values.data(), bytes.data(), bytes.size());
      return values;
    }

    /// Copy the array @p name into the @p n values at @p values (it must
    /// have exactly @p n).
    void
    get(const std::string &name, double *values, std::size_t n) const;

    /// Fill this rank's entries of @p v (laid out as when it was put).
    template <class VectorType>
    void
    get_owned(const std::string &name, VectorType &v) const
    {
      get(name, v.begin(), v.locally_owned_size());
    }

    std::string
    get_text(const std::string &name) const
    {
      return entry(name, 0);
    }

    /**
     * Write to @p file: into `file.tmp`, flushed to the disk (fsync),
     * then renamed. Returns an empty string, or why it failed.
     */
    std::string
    write(const std::string &file) const;

    /// Read @p file (InputError naming it if it is missing or not a whole
    /// archive).
    static StateArchive
    read(const std::string &file);

  private:
    std::map<std::string, std::string> entries;
    /// The file it was read from (messages).
    std::string source;

    void
    put_bytes(const std::string &name, const void *data, std::size_t n);

    /// The entry @p name, of @p size bytes unless 0 (InputError).
    const std::string &
    entry(const std::string &name, std::size_t size) const;

    [[noreturn]] void
    wrong_size(const std::string &name,
               std::size_t        size,
               std::size_t        unit) const;
  };
} // namespace pdfem

#endif
