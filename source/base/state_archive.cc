// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fcntl.h>
#include <unistd.h>

namespace pdfem
{
  namespace
  {
    const std::string magic = "pdfem state archive 1\n";

    /// FNV-1a, 64 bits: cheap, and any truncation or changed byte shows.
    std::uint64_t
    checksum(const std::string &bytes)
    {
      std::uint64_t h = 14695981039346656037ull;
      for (const char c : bytes)
        {
          h ^= static_cast<unsigned char>(c);
          h *= 1099511628211ull;
        }
      return h;
    }

    void
    append_size(std::string &out, const std::uint64_t n)
    {
      out.append(reinterpret_cast<const char *>(&n), sizeof(n));
    }
  } // namespace

  void
  StateArchive::put_bytes(const std::string &name,
                          const void        *data,
                          const std::size_t  n)
  {
    entries[name].assign(static_cast<const char *>(data), n);
  }

  const std::string &
  StateArchive::entry(const std::string &name, const std::size_t size) const
  {
    const auto it = entries.find(name);
    if (it == entries.end())
      throw InputError(source,
                       "",
                       "the checkpoint has no entry '" + name +
                         "' (written by another version of pdfem, or for "
                         "another kind of run)");
    if (size != 0 && it->second.size() != size)
      wrong_size(name, it->second.size(), size);
    return it->second;
  }

  void
  StateArchive::wrong_size(const std::string &name,
                           const std::size_t  size,
                           const std::size_t  unit) const
  {
    throw InputError(source,
                     "",
                     "the checkpoint's entry '" + name + "' has " +
                       std::to_string(size) + " bytes, not a multiple of " +
                       std::to_string(unit) +
                       " (written by another version of pdfem?)");
  }

  void
  StateArchive::get(const std::string &name,
                    double            *values,
                    const std::size_t  n) const
  {
    const std::string &bytes = entry(name, 0);
    if (bytes.size() != n * sizeof(double))
      throw InputError(source,
                       "",
                       "the checkpoint's '" + name + "' has " +
                         std::to_string(bytes.size() / sizeof(double)) +
                         " values where this run has " + std::to_string(n) +
                         " (another mesh, or another number of ranks?)");
    if (n > 0)
      std::memcpy(values, bytes.data(), bytes.size());
  }

  std::string
  StateArchive::write(const std::string &file) const
  {
    std::string body;
    append_size(body, entries.size());
    for (const auto &[name, bytes] : entries)
      {
        append_size(body, name.size());
        body += name;
        append_size(body, bytes.size());
        body += bytes;
      }
    append_size(body, checksum(body));
    const std::string content = magic + body;

    const std::string temporary = file + ".tmp";
    const int         fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
      return "cannot create " + temporary + ": " + std::strerror(errno);
    std::string error;
    for (std::size_t done = 0; done < content.size() && error.empty();)
      {
        const ssize_t n =
          ::write(fd, content.data() + done, content.size() - done);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          error = "writing " + temporary + " failed: " + std::strerror(errno);
        else
          done += static_cast<std::size_t>(n);
      }
    // The bytes on the disk before the name points to them.
    if (error.empty() && ::fsync(fd) != 0)
      error = "flushing " + temporary + " failed: " + std::strerror(errno);
    if (::close(fd) != 0 && error.empty())
      error = "closing " + temporary + " failed: " + std::strerror(errno);
    if (error.empty() && std::rename(temporary.c_str(), file.c_str()) != 0)
      error = "renaming " + temporary + " failed: " + std::strerror(errno);
    if (!error.empty())
      std::remove(temporary.c_str());
    return error;
  }

  StateArchive
  StateArchive::read(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw InputError(file, "", "cannot read the checkpoint file");
    const std::string content{std::istreambuf_iterator<char>(in), {}};
    const auto        broken = [&](const std::string &why) {
      return InputError(file,
                        "",
                        "not a whole checkpoint file (" + why +
                          "): it was cut short or altered");
    };
    if (content.compare(0, magic.size(), magic) != 0)
      throw broken("no pdfem state archive header");
    const std::string body = content.substr(magic.size());
    if (body.size() < 2 * sizeof(std::uint64_t))
      throw broken("too short");
    std::uint64_t stored;
    std::memcpy(&stored,
                body.data() + body.size() - sizeof(stored),
                sizeof(stored));
    const std::string entries_part =
      body.substr(0, body.size() - sizeof(stored));
    if (checksum(entries_part) != stored)
      throw broken("checksum differs");

    StateArchive archive;
    archive.source        = file;
    std::size_t pos       = 0;
    const auto  next_size = [&]() {
      std::uint64_t n;
      if (pos + sizeof(n) > entries_part.size())
        throw broken("entry past the end");
      std::memcpy(&n, entries_part.data() + pos, sizeof(n));
      pos += sizeof(n);
      return n;
    };
    const auto next_bytes = [&](const std::uint64_t n) {
      if (n > entries_part.size() - pos)
        throw broken("entry past the end");
      std::string bytes = entries_part.substr(pos, n);
      pos += n;
      return bytes;
    };
    const std::uint64_t n_entries = next_size();
    for (std::uint64_t e = 0; e < n_entries; ++e)
      {
        const std::string name = next_bytes(next_size());
        archive.entries[name]  = next_bytes(next_size());
      }
    if (pos != entries_part.size())
      throw broken("bytes after the last entry");
    return archive;
  }
} // namespace pdfem
