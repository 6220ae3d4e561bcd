// SPDX-License-Identifier: GPL-2.0-or-later
// (placeholder: filled by the tangential-law work of issue 4)
#include <gtest/gtest.h>
