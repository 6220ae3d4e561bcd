// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: the headers and names every part of the tool uses. The tool is one translation unit
// (main.cpp) in parts: fit_options.h (the -h text, options, the fitting context), fit_one.h
// (weights, residuals, one minimisation), main.cpp (choice of the best law, output, main). Each part
// opens the same unnamed namespace.
#pragma once

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fit_laws.h"
#include "tabulate.h"
#include "impact_data.h"
#include "nelder_mead.h"

namespace {

using namespace tdem;
using namespace tdem::fitting;

}  // namespace
