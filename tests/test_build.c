/* Build invariants: floating-point contraction is off (-ffp-contract=off), so a*b + c is the
   rounded product plus c, never a fused multiply-add: results do not depend on the CPU. */
#include "check.h"

int main(void) {
    /* a*a = 1 + 2^-26 + 2^-54 exactly; rounded, the 2^-54 is lost and a*a - 1 = 2^-26 */
    volatile double a = 1.0 + 0x1p-27, c = -(1.0 + 0x1p-26);
    double r = a * a + c;
    CHECK(r == 0.0); /* a fused multiply-add would give 2^-54 */
    return CHECK_DONE();
}
