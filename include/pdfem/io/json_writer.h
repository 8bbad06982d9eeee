// SPDX-License-Identifier: LGPL-2.1-or-later
// The JSON writer lives in base/ (drivers and plugins below io write their
// summary.json sections with it); this header keeps the old path.
#include <pdfem/base/json_writer.h>
