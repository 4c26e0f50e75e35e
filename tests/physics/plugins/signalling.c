/* Test plugin (vehicle_signals_test.cpp): a version 2 plugin that drives straight on at a
 * constant 1 m/s^2 and shows the left indicator and the wipers throughout, and the hazard
 * lights while it perceives a vehicle showing its low beams (object_signals). */
#include <stdlib.h>

#include "ego_plugin.h"

typedef struct nothing {
  int unused;
} nothing;

uint32_t scenfuzz_ego_abi_version(void) { return SCENFUZZ_EGO_ABI_VERSION; }

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  if (config->abi_version != 2) return NULL;
  return calloc(1, sizeof(nothing));
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  uint32_t i, signals = SCENFUZZ_SIGNAL_LEFT_INDICATOR | SCENFUZZ_SIGNAL_WIPERS;
  (void)driver;
  for (i = 0; i < observation->object_count; ++i)
    if (observation->objects[i].kind == SCENFUZZ_OBJECT_VEHICLE &&
        (observation->object_signals[i] & SCENFUZZ_SIGNAL_LOW_BEAM) != 0)
      signals |= SCENFUZZ_SIGNAL_HAZARD_LIGHTS;
  control->acceleration = 1;
  control->steering_angle = 0;
  control->version = SCENFUZZ_EGO_ABI_VERSION;
  control->signals = signals;
  return 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
