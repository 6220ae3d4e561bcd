// SPDX-License-Identifier: GPL-2.0-or-later
// physics_reference.md 8.5: oblique sphere-wall impacts, LSD + Cundall-Strack, kappa = 2/7 (an
// independent fine-step reference), shared by the oblique-harness and closed-form tests.
#pragma once

namespace tdem_test {

struct Row85 {
  double theta, beta, e_t, omega, rebound, slip_in, slip_out;
};

inline constexpr Row85 kTable85[] = {
    {5, +0.99989, 0.42860, -194.22, -5.101, 0.9510, -0.9509},
    {10, +0.99982, 0.42862, -386.95, -10.197, 1.9166, -1.9163},
    {15, +0.99947, 0.42872, -576.64, -15.283, 2.9125, -2.9110},
    {20, +0.75121, 0.49965, -667.40, -15.588, 3.9562, -2.9719},
    {25, +0.36718, 0.60938, -643.83, -9.910, 5.0686, -1.8611},
    {30, +0.10427, 0.68449, -615.24, -3.515, 6.2755, -0.6544},
    {40, -0.24017, 0.78291, -544.23, +11.620, 9.1206, +2.1905},
    {60, -0.63189, 0.89483, -355.22, +48.156, 18.8266, +11.8964},
    {80, -0.88758, 0.96788, -123.37, +78.982, 61.6444, +54.7141},
};

}  // namespace tdem_test
