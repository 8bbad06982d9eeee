// SPDX-License-Identifier: LGPL-2.1-or-later
// The driver family: its registry and the defaults of Drivers::Interface.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/drivers/interface.h>

namespace pdfem
{
  namespace Drivers
  {
    Plugins::Registry<Interface> &
    registry()
    {
      static Plugins::Registry<Interface> drivers;
      return drivers;
    }

    std::unique_ptr<Interface>
    create(const std::string &name, const std::string &file)
    {
      return registry().create(name, file, "Driver/Type", "driver");
    }

    void
    Interface::parse_parameters(dealii::ParameterHandler &prm,
                                const std::string        &file,
                                const int                 dim)
    {
      Settings parsed;
      parsed.parse(prm, file, dim);
      initialize(parsed, file, dim);
    }

    void
    Interface::initialize(const Settings &settings, const std::string &, int)
    {
      parameters = settings;
    }

    void
    Interface::check(const RunTraits &traits) const
    {
      if (traits.nonlinear_model && !handles_nonlinear_models())
        throw InputError(traits.file,
                         "Driver/Type",
                         "the " + traits.model_name +
                           " model softens its bonds itself: it takes no " +
                           traits.driver_name + " driver",
                         "a driver for nonlinear models (newton, arc length, "
                         "static)");
    }

    void
    Interface::write_summary(IO::JsonWriter &) const
    {}
  } // namespace Drivers
} // namespace pdfem
