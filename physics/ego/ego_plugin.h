/* The C ABI through which another driver takes the ego's wheel (docs/ego-plugin.md).
 *
 * A plugin is a shared library exporting the three functions below. scenfuzz loads it in a
 * child process for each evaluation, so a plugin that crashes or hangs costs that evaluation
 * only. Every step (dt seconds of simulated time) the plugin gets an observation (its own
 * state, what its perception saw, the route ahead, the next traffic light and stop sign) and
 * returns a control (acceleration and front-wheel steering angle, and from ABI version 2 the
 * vehicle's signals), which scenfuzz applies to the ego with the kinematic bicycle model of its
 * vehicle class.
 *
 * Versions: version 2 appended fields to scenfuzz_observation and scenfuzz_control and added the
 * optional scenfuzz_ego_abi_version function; nothing before them moved, so a plugin built
 * against version 1 runs unchanged (its signals read as off).
 *
 * All structs are plain C with fixed-size arrays so that they cross a pipe unchanged; all
 * quantities are SI (m, s, m/s, m/s^2, rad) in the map's ENU frame, headings counter-clockwise
 * from east. Plain C99: this header must stay includable from C and C++. */
#ifndef SCENFUZZ_EGO_PLUGIN_H
#define SCENFUZZ_EGO_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SCENFUZZ_EGO_ABI_VERSION 2
#define SCENFUZZ_MAX_OBJECTS 64
#define SCENFUZZ_ROUTE_POINTS 64

/* The vehicle signals (version 2): bits of scenfuzz_control.signals and of
 * scenfuzz_observation.object_signals. */
#define SCENFUZZ_SIGNAL_LEFT_INDICATOR 0x001u
#define SCENFUZZ_SIGNAL_RIGHT_INDICATOR 0x002u
#define SCENFUZZ_SIGNAL_HAZARD_LIGHTS 0x004u /* both indicators flashing */
#define SCENFUZZ_SIGNAL_HORN 0x008u
#define SCENFUZZ_SIGNAL_LOW_BEAM 0x010u
#define SCENFUZZ_SIGNAL_HIGH_BEAM 0x020u
#define SCENFUZZ_SIGNAL_FOG_LIGHTS 0x040u
#define SCENFUZZ_SIGNAL_WIPERS 0x080u
#define SCENFUZZ_SIGNAL_BRAKE_LIGHTS 0x100u /* scenfuzz adds it whenever the ego brakes */

typedef struct scenfuzz_vehicle {
  double length, width, wheelbase;
  double max_speed, max_acceleration, max_deceleration;
  double max_steering_angle;
} scenfuzz_vehicle;

typedef struct scenfuzz_ego_config {
  /* The version both sides speak: the plugin's (scenfuzz_ego_abi_version, 1 when it does not
   * export it), or scenfuzz's SCENFUZZ_EGO_ABI_VERSION if that is lower. */
  uint32_t abi_version;
  double dt;     /* seconds per step */
  uint64_t seed; /* for any randomness the driver has: use it, so runs repeat */
  scenfuzz_vehicle vehicle;
  double target_x, target_y; /* where the ego must go; NaN when the scenario gives no target */
} scenfuzz_ego_config;

typedef struct scenfuzz_ego_state {
  double time;
  double x, y, heading, speed, acceleration, yaw_rate, steering_angle;
} scenfuzz_ego_state;

enum scenfuzz_object_kind {
  SCENFUZZ_OBJECT_VEHICLE = 0,
  SCENFUZZ_OBJECT_PEDESTRIAN = 1,
  SCENFUZZ_OBJECT_OBSTACLE = 2
};

/* One perceived object: as the perception model saw it (noisy, possibly late). */
typedef struct scenfuzz_object {
  uint32_t id;   /* stable across steps */
  uint32_t kind; /* enum scenfuzz_object_kind */
  double x, y, heading, speed;
  double length, width;
} scenfuzz_object;

/* A point of the route's centre line ahead of the ego, about 2 m apart, the first one at the
 * ego's projection onto the route. */
typedef struct scenfuzz_route_point {
  double x, y, heading;
  double speed_limit; /* m/s */
} scenfuzz_route_point;

enum scenfuzz_light {
  SCENFUZZ_LIGHT_NONE = -1,
  SCENFUZZ_LIGHT_RED = 0,
  SCENFUZZ_LIGHT_YELLOW = 1,
  SCENFUZZ_LIGHT_GREEN = 2
};

typedef struct scenfuzz_environment {
  double darkness, fog, rain, snow;
} scenfuzz_environment;

typedef struct scenfuzz_observation {
  scenfuzz_ego_state ego;
  uint32_t object_count; /* nearest first, at most SCENFUZZ_MAX_OBJECTS */
  scenfuzz_object objects[SCENFUZZ_MAX_OBJECTS];
  uint32_t route_point_count;
  scenfuzz_route_point route[SCENFUZZ_ROUTE_POINTS];
  double distance_to_target; /* along the route; INFINITY without a target */
  int32_t light;             /* enum scenfuzz_light: the next signal on the route */
  double light_distance;     /* to its stop line; INFINITY when light is NONE */
  double stop_sign_distance; /* to the next stop sign's line on the route; INFINITY if none */
  /* Version 2: the signals (SCENFUZZ_SIGNAL_*) of objects[i] as perceived, as late as the rest
   * of it; 0 for pedestrians and obstacles. */
  uint32_t object_signals[SCENFUZZ_MAX_OBJECTS];
  /* Version 2: the weather and light of the run (the same every step), each in [0, 1]: 0 none
   * (daylight), 1 the heaviest (night without street light). What a driver needs to choose its
   * lights and wipers. */
  scenfuzz_environment environment;
} scenfuzz_observation;

typedef struct scenfuzz_control {
  double acceleration;   /* m/s^2; negative brakes; clamped to the vehicle's limits */
  double steering_angle; /* rad, front wheel, positive left; clamped */
  /* Version 2. scenfuzz zero-fills the control before each step, so a version 1 plugin, which
   * writes only the fields above, leaves version 0: its signals are off. */
  uint32_t version; /* the ABI version the plugin speaks: SCENFUZZ_EGO_ABI_VERSION */
  uint32_t signals; /* SCENFUZZ_SIGNAL_* bits; read only when version >= 2 */
} scenfuzz_control;

/* Returns the driver's state, or NULL on failure (the evaluation is reported as failed). */
void* scenfuzz_ego_create(const scenfuzz_ego_config* config);
/* Fills `control`; returns 0, or non-zero on failure (the evaluation is reported as failed). */
int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control);
void scenfuzz_ego_destroy(void* driver);
/* Optional (version 2): the ABI version the plugin was built against, SCENFUZZ_EGO_ABI_VERSION.
 * A plugin that does not export it is taken to speak version 1, and its config says 1. */
uint32_t scenfuzz_ego_abi_version(void);

#ifdef __cplusplus
}
#endif

#endif
