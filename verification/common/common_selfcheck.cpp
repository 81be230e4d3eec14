// Hand-computed checks of the verification helpers (norms, orders, column decks, the
// diffusion series), so that a wrong helper cannot make a verification case pass.
#include <cmath>
#include <iostream>
#include <string>

#include "ColumnRun.hpp"
#include "DiffusionSeries.hpp"
#include "ProfileNorms.hpp"
#include "VerificationMain.hpp"

namespace av = argine::verification;

namespace {

int failures = 0;

void expectNear(const std::string& what, double value, double expected, double tolerance) {
  if (std::fabs(value - expected) <= tolerance) return;
  std::cout << "FAIL " << what << ": " << value << ", expected " << expected << "\n";
  ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, [](int, char**) {
    // Two points, weights 1 and 3; numerical (0.5, 0.2), reference (0.4, 0.3), initial 1:
    // error (0.1, -0.1): ||e|| = sqrt(0.01 + 3 x 0.01) = 0.2;
    // ||ref|| = sqrt(0.16 + 3 x 0.09) = sqrt(0.43) = 0.655744;
    // ||ref - 1|| = sqrt(0.36 + 3 x 0.49) = sqrt(1.83) = 1.352775.
    const av::ProfileError e = av::profileError({0.5, 0.2}, {0.4, 0.3}, {1, 1}, {1, 3});
    expectNear("relative", e.relative, 0.2 / 0.655744, 1e-6);
    expectNear("of_change", e.of_change, 0.2 / 1.352775, 1e-6);
    expectNear("governing", e.governing(), 0.2 / 0.655744, 1e-6);
    expectNear("max_abs", e.max_abs, 0.1, 1e-12);
    // Element means: points 0, 1 in element 0 (V 1, 1), point 2 in element 1 (V 2).
    // numerical (1, 3, 2) -> means (2, 2); reference (2, 2, 1) -> means (2, 1);
    // error (0, 1), element volumes (2, 2): ||e|| = sqrt(2), ||ref|| = sqrt(8 + 2) = sqrt(10).
    expectNear("element means", av::elementMeanError({1, 3, 2}, {2, 2, 1}, {1, 1, 2}, {0, 0, 1}),
               std::sqrt(2.0 / 10.0), 1e-12);
    // Halving h divides the error by 4: order 2.
    expectNear("order", av::observedOrder(0.08, 0.02, 2.0), 2.0, 1e-12);
    // Series: u(0, T = 1) = (4/pi)(e^{-pi^2/4} - e^{-9 pi^2/4}/3) = 1.273240 x 0.084804
    // = 0.107977; U(T = 1) = 1 - (8/pi^2)(e^{-pi^2/4} + e^{-9 pi^2/4}/9) = 1 - 0.810569 x
    // 0.084804 = 0.931260; u(h, T) = 0.
    expectNear("series u(0, 1)", av::drainedTopSeries(0.0, 1.0), 0.107977, 2e-6);
    expectNear("series U(1)", av::drainedTopDegree(1.0), 0.931260, 2e-6);
    expectNear("series u(h, 0.05)", av::drainedTopSeries(1.0, 0.05), 0.0, 1e-12);
    // Early times: U = sqrt(4T/pi) for U < 0.6, so U(0.01) = 0.112838.
    expectNear("series U(0.01)", av::drainedTopDegree(0.01), 0.112838, 2e-6);

    // A column of 8 elements over [0, 2] m: element size 0.25 m, width 0.25 m.
    argine::Deck deck;
    deck.mesh.generate = true;
    deck.mesh.generator.lower_left = {0.0, 0.0};
    deck.mesh.generator.upper_right = {0.1, 2.0};
    const argine::Deck column = av::columnDeck(deck, 8);
    expectNear("column element size", column.mesh.generator.element_size, 0.25, 1e-15);
    expectNear("column width", column.mesh.generator.upper_right[0], 0.25, 1e-15);
    expectNear("column height", column.mesh.generator.upper_right[1], 2.0, 0.0);

    std::cout << (failures ? "verification helpers: FAILED" : "verification helpers: passed")
              << "\n";
    return failures ? av::kExitBoundExceeded : 0;
  });
}
