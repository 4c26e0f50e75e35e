/* Test plugin (vehicle_signals_test.cpp): built against the version 1 header (a copy in v1/), as
 * a plugin written before vehicle signals existed. It insists on abi_version 1, as such plugins
 * did, and drives straight on at a constant 1 m/s^2, writing only the version 1 control. */
#include <stdlib.h>

#include "v1/ego_plugin.h"

typedef struct nothing {
  int unused;
} nothing;

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  if (config->abi_version != 1) return NULL;
  return calloc(1, sizeof(nothing));
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  (void)driver;
  (void)observation;
  control->acceleration = 1;
  control->steering_angle = 0;
  return 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
