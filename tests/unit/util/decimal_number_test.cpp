// Decimal numbers past double's range: underflow is 0 (as a subnormal is close to it),
// overflow is reported, decided by the number's magnitude, not its exponent's sign alone.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "framework/util/decimal_number.h"

using namespace subdiv;

TEST_CASE("parse_decimal: underflow is a signed 0, overflow a signed infinity, whatever the mantissa") {
  double v = 1;
  CHECK(parse_decimal("4e-320", v) == DecimalParse::ok);
  CHECK(v == 4e-320);
  CHECK(parse_decimal("1e-400", v) == DecimalParse::ok);
  CHECK((v == 0 && !std::signbit(v)));
  CHECK(parse_decimal("-1e-400", v) == DecimalParse::ok);
  CHECK((v == 0 && std::signbit(v)));
  CHECK(parse_decimal("1000e-400", v) == DecimalParse::ok);
  CHECK(v == 0);
  // 10^-501 written with a positive exponent, 10^309 with a negative one.
  CHECK(parse_decimal("0." + std::string(500, '0') + "1e100", v) == DecimalParse::ok);
  CHECK(v == 0);
  CHECK(parse_decimal("1" + std::string(319, '0') + "e-10", v) == DecimalParse::overflow);
  CHECK(v == INFINITY);
  CHECK(parse_decimal("-1e400", v) == DecimalParse::overflow);
  CHECK(v == -INFINITY);
  CHECK(parse_decimal("+1e-99999999999999999999999", v) == DecimalParse::ok);
  CHECK(v == 0);
  CHECK(parse_decimal("1e99999999999999999999999", v) == DecimalParse::overflow);
}

TEST_CASE("parse_decimal: a leading '+', and what is not a number") {
  double v = 0;
  CHECK(parse_decimal("+0.25", v) == DecimalParse::ok);
  CHECK(v == 0.25);
  for (const char* bad : {"", "+", "+-1", "++1", "1,5", " 1", "1 ", "0x1p3", "1e", "--1"}) {
    CAPTURE(bad);
    CHECK(parse_decimal(bad, v) == DecimalParse::not_a_number);
  }
  CHECK(parse_decimal("nan", v) == DecimalParse::ok);  // for the caller to refuse as non-finite
  CHECK(std::isnan(v));
}
