#pragma once
// The Hertz law's damping ratio for en = 0.01, 0.02, ..., 0.99 (entry k - 1 for en = k/100):
// solve_hertz_damping_ratio's results to the last bit (hex floats), so a run need not spend the
// ~2.2e9 instructions of a solve at start-up. Printed by `tests_contact "[.hertz_damping_table]"`,
// which checks every entry against the solve; CI checks en 0.1 and 0.9
// (tests/contact/test_law_hertz.cpp).

#include <array>

namespace polydem {

inline constexpr std::array<double, 99> kHertzDampingRatio = {
    0x1.18d6eab92p+2, 0x1.81f02fd44p+1, 0x1.3335d0df4p+1, 0x1.03dd0d3aap+1,
    0x1.c69e1adb4p+0, 0x1.963c6343cp+0, 0x1.70686950cp+0, 0x1.51bf7a3ccp+0,
    0x1.383906a0cp+0, 0x1.2286d8036p+0, 0x1.0fc71f916p+0, 0x1.feb606204p-1,
    0x1.e19e12284p-1, 0x1.c799e2064p-1, 0x1.b025a0cccp-1, 0x1.9ada9215cp-1,
    0x1.8767490a4p-1, 0x1.758a47aa4p-1, 0x1.650e305c4p-1, 0x1.55c706574p-1,
    0x1.4790279ccp-1, 0x1.3a4ac9c0cp-1, 0x1.2ddcd3b14p-1, 0x1.222ffb812p-1,
    0x1.1731163b2p-1, 0x1.0ccf8d24ep-1, 0x1.02fcef682p-1, 0x1.f3593311cp-2,
    0x1.e1a6db524p-2, 0x1.d0cf321d4p-2, 0x1.c0c0c8044p-2, 0x1.b16c13f7cp-2,
    0x1.a2c33107cp-2, 0x1.94b9a6d44p-2, 0x1.87443a9c4p-2, 0x1.7a58c7a5cp-2,
    0x1.6dee1d774p-2, 0x1.61fbe303cp-2, 0x1.567a7dc0cp-2, 0x1.4b62fc5c4p-2,
    0x1.40af04414p-2, 0x1.3658c145cp-2, 0x1.2c5ad7f24p-2, 0x1.22b058faap-2,
    0x1.1954b67d2p-2, 0x1.1043baa9ap-2, 0x1.07797f34ap-2, 0x1.fde4cbe94p-3,
    0x1.ed5624b1cp-3, 0x1.dd40c6ed4p-3, 0x1.cd9eddb44p-3, 0x1.be6af7924p-3,
    0x1.af9ffe2acp-3, 0x1.a1392ebccp-3, 0x1.9332134c4p-3, 0x1.85867c714p-3,
    0x1.78327bc6cp-3, 0x1.6b325f254p-3, 0x1.5e82abb2cp-3, 0x1.52201a174p-3,
    0x1.460792914p-3, 0x1.3a3629894p-3, 0x1.2ea91c5d4p-3, 0x1.235dcec22p-3,
    0x1.1851c7d62p-3, 0x1.0d82aff82p-3, 0x1.02ee4e552p-3, 0x1.f1250e32cp-4,
    0x1.dcdab3024p-4, 0x1.c8f9bc08cp-4, 0x1.b57e89b54p-4, 0x1.a265a8ebcp-4,
    0x1.8fabd0744p-4, 0x1.7d4dde30cp-4, 0x1.6b48d4fecp-4, 0x1.5999da93cp-4,
    0x1.483e352bcp-4, 0x1.37334a204p-4, 0x1.26769bc02p-4, 0x1.1605c7daep-4,
    0x1.05de86462p-4, 0x1.ebfd4eeacp-5, 0x1.ccc8263a4p-5, 0x1.ae198d88cp-5,
    0x1.8fedaa2f4p-5, 0x1.7240c8d5cp-5, 0x1.550f5b724p-5, 0x1.3855f7f54p-5,
    0x1.1c11561e2p-5, 0x1.003e4dbfep-5, 0x1.c9b3aa61cp-6, 0x1.93c2005e4p-6,
    0x1.5ea1fb97cp-6, 0x1.2a4e3002cp-6, 0x1.ed82c5bfcp-7, 0x1.87ed14a04p-7,
    0x1.23d19399ep-7, 0x1.824dc1e24p-8, 0x1.7f8fbc594p-9};

}  // namespace polydem
