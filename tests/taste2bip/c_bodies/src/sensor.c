/* Sensor: a level that rises by the context parameter step each period, added up by
   Accumulator and reported to Monitor. */
#include "sensor.h"
#include "Context-sensor.h"

#include <stdio.h>

static asn1SccT_Level level;

void sensor_startup(void)
{
    level = 0;
}

void sensor_PI_tick(void)
{
    asn1SccT_Level total = 0;
    asn1SccT_Report report;

    level += sensor_ctxt.step;
    sensor_RI_add(&level, &total);
    report.total = total;
    report.alarm = total >= 20;
    printf("sensor: level %" PRIu64 ", total %" PRIu64 "%s\n", level, total,
           report.alarm ? ", alarm" : "");
    sensor_RI_report(&report);
}
