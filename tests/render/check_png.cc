// SPDX-License-Identifier: LGPL-2.1-or-later
// check_png: does a PNG look like a picture? Used by the render.* tests.
//
//   check_png FILE.png WIDTH HEIGHT MIN_COLOURS
//
// Checks that FILE.png can be read, is WIDTH x HEIGHT pixels (0 0: any size),
// has at least MIN_COLOURS distinct colours and that no single colour (the
// background) covers more than 90 % of it. Prints one line; exit status 0 when
// every check holds, 1 otherwise.
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
  if (argc != 5)
    {
      std::cerr << "usage: check_png FILE.png WIDTH HEIGHT MIN_COLOURS\n";
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
  if (background > 0.9)
    {
      std::cout << "check_png: FAILED: one colour covers more than 90 %\n";
      ok = false;
    }
  return ok ? 0 : 1;
}
