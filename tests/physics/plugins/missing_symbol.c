/* Test plugin (plugin_driver_test.cpp): exports create and destroy but no scenfuzz_ego_step,
 * so loading must fail with a message naming the symbol. */
#include <stdlib.h>

#include "ego_plugin.h"

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  (void)config;
  return malloc(1);
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
