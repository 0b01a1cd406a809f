/* Accumulator: the running total of the values it is given. */
#include "accumulator.h"

static asn1SccT_Level sum;

void accumulator_startup(void)
{
    sum = 0;
}

void accumulator_PI_add(const asn1SccT_Level *IN_value, asn1SccT_Level *OUT_total)
{
    sum += *IN_value;
    *OUT_total = sum;
}
