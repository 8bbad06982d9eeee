// SPDX-License-Identifier: LGPL-2.1-or-later
// check_png: does a PNG look like a picture? Used by the render.* tests.
//
//   check_png FILE.png WIDTH HEIGHT MIN_COLOURS [P%] [R,G,B ...]
//
// Checks that FILE.png can be read, is WIDTH x HEIGHT pixels (0 0: any size),
// has at least MIN_COLOURS distinct colours, that no single colour (the
// background) covers more than P % of it (default 90; charts are mostly
// white) and that each colour R,G,B given (e.g. a chart's series colours)
// covers at least 20 pixels. Prints what it found; exit status 0 when every
// check holds, 1 otherwise.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

int
main(int argc, char **argv)
{
  if (argc < 5)
    {
      std::cerr
        << "usage: check_png FILE.png WIDTH HEIGHT MIN_COLOURS [P%] [R,G,B ...]\n";
      return 2;
    }
  const std::string file        = argv[1];
  const int         width       = std::atoi(argv[2]);
  const int         height      = std::atoi(argv[3]);
  const long        min_colours = std::atol(argv[4]);

  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(file.c_str()))
    {
      std::cout << "check_png: FAILED: " << file << " is not a readable PNG\n";
      return 1;
    }
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData *image = reader->GetOutput();
  int           dims[3];
  image->GetDimensions(dims);
  const int n_components = image->GetNumberOfScalarComponents();

  std::map<unsigned long, long> colours;
  const auto                   *pixel =
    static_cast<const unsigned char *>(image->GetScalarPointer(0, 0, 0));
  const long n_pixels = static_cast<long>(dims[0]) * dims[1];
  for (long i = 0; i < n_pixels; ++i, pixel += n_components)
    {
      unsigned long key = 0;
      for (int c = 0; c < std::min(n_components, 3); ++c)
        key = key * 256 + pixel[c];
      ++colours[key];
    }
  long most = 0;
  for (const auto &entry : colours)
    most = std::max(most, entry.second);
  const double background = n_pixels > 0 ? 1.0 * most / n_pixels : 1.0;

  std::cout << "check_png: " << file << ": " << dims[0] << " x " << dims[1]
            << " pixels, " << colours.size() << " colours, the commonest on "
            << static_cast<int>(100 * background) << " %\n";
  bool ok = true;
  if ((width > 0 || height > 0) && (dims[0] != width || dims[1] != height))
    {
      std::cout << "check_png: FAILED: expected " << width << " x " << height
                << " pixels\n";
      ok = false;
    }
  if (static_cast<long>(colours.size()) < min_colours)
    {
      std::cout << "check_png: FAILED: expected at least " << min_colours
                << " colours (a blank picture?)\n";
      ok = false;
    }
  int first_colour = 5;
  int max_percent  = 90;
  if (argc > 5 && std::string(argv[5]).back() == '%')
    {
      max_percent  = std::atoi(argv[5]);
      first_colour = 6;
    }
  if (background > max_percent / 100.0)
    {
      std::cout << "check_png: FAILED: one colour covers more than "
                << max_percent << " %\n";
      ok = false;
    }
  for (int i = first_colour; i < argc; ++i)
    {
      int r = -1, g = -1, b = -1;
      if (std::sscanf(argv[i], "%d,%d,%d", &r, &g, &b) != 3)
        {
          std::cerr << "check_png: a colour is R,G,B, got '" << argv[i]
                    << "'\n";
          return 2;
        }
      const auto it =
        colours.find((static_cast<unsigned long>(r) * 256 + g) * 256 + b);
      const long n = it == colours.end() ? 0 : it->second;
      std::cout << "check_png: colour " << argv[i] << " on " << n
                << " pixels\n";
      if (n < 20)
        {
          std::cout << "check_png: FAILED: expected at least 20 pixels of "
                    << argv[i] << "\n";
          ok = false;
        }
    }
  return ok ? 0 : 1;
}
