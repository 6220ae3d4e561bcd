// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the headers and names every part of the tool uses. The tool is one translation
// unit (main.cpp) in parts: collide_help.h (the -h text), collide_args.h (options and JSON),
// collide_oblique.h (oblique impacts and --scheme), collide_analytic.h (--analytic), main.cpp
// (the laws from the options, output, main). Each part opens the same unnamed namespace.
#pragma once

#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "collision/conversions.h"
#include "collision/head_on.h"
#include "collision/analytic.h"
#include "collision/integrate_impact.h"
#include "collision/phase_average.h"
#include "collision/oblique.h"
#include "collision/rigid_body.h"
#include "contact/laws.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/haff_werner.h"
#include "contact/tangential/linear_spring.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/parameters.h"
#include "contact/tangential/walton_braun_tangential.h"

namespace {

using namespace tdem;
using tdem::collision::Bodies;

}  // namespace
