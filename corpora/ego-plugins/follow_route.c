/* An example ego plugin (docs/ego-plugin.md): a simple but careful driver that uses only its
 * observation. Copy it to start your own.
 *
 * - Steering: pure pursuit on the route's points, from the rear axle, looking ahead
 *   max(5 m, 0.8 s * speed).
 * - Speed: the route's speed limit (at most 15 m/s), slower before bends (lateral acceleration
 *   at most 2 m/s^2) and before lower limits ahead, reached with an IDM-like controller.
 * - Following: a time gap of 2 s (plus 2 m standstill) to the nearest object ahead whose centre
 *   is within 2 m of the route's centre line (the intelligent driver model).
 * - Stopping: at a red light's line, at a yellow one's when there is room, at a stop sign's line
 *   (then on after standing 1 s), at the target, and at the end of a route that ends.
 * - Signals (ABI version 2): the indicator towards a turn of the route (its heading turning by
 *   more than 30 degrees within max(30 m, 3 s of travel) ahead) until the turn is nearly done;
 *   low beams from dusk and in fog, fog lights in fog (0.2 and thicker), wipers in rain or snow.
 *   scenfuzz adds the brake lights itself whenever the plugin brakes.
 *
 * Deterministic and without randomness, so config->seed is not needed here.
 * Build: gcc -std=c99 -shared -fPIC -O2 -Wall -I<repo>/physics/ego follow_route.c \
 *            -o libfollow_route.so -lm */
#include <math.h>
#include <stdlib.h>

#include "ego_plugin.h"

#define CRUISE_SPEED_CAP 15.0    /* m/s */
#define LATERAL_ACCELERATION 2.0 /* m/s^2 allowed in bends */
#define COMFORTABLE_DECELERATION 2.5
#define TIME_GAP 2.0       /* s */
#define STANDSTILL_GAP 2.0 /* m */
#define ROUTE_CORRIDOR 2.0 /* m: objects whose centre is this close to the route are in the way */
#define STOP_MARGIN 0.5    /* m between the front bumper and a stop line */
#define STOP_SIGN_WAIT 1.0 /* s standing at a stop sign before going on */
#define PI 3.14159265358979323846
#define INDICATE_DISTANCE 30.0 /* m: indicate at least this far before a turn */
#define INDICATE_TIME 3.0      /* s: and at least this long before it */
#define TURN_ANGLE 0.5236      /* rad (30 degrees): the route turns by more than this */
#define THICK_FOG 0.2          /* environment.fog from which fog lights go on */

typedef struct driver {
  scenfuzz_ego_config config;
  double comfortable_deceleration;
  double stopped_at_sign_since; /* time the ego stood at the current stop sign; NAN if not */
  int sign_cleared;             /* 1 once the ego may pass the current stop sign */
  double last_sign_distance;
} driver;

static double clamp(double value, double low, double high) {
  return value < low ? low : (value > high ? high : value);
}

static double wrap_angle(double angle) {
  while (angle > PI) angle -= 2.0 * PI;
  while (angle < -PI) angle += 2.0 * PI;
  return angle;
}

/* Built against version 2 (the observation's object_signals and environment, the control's
 * signals): scenfuzz tells create the version both speak, and this plugin needs its own. */
uint32_t scenfuzz_ego_abi_version(void) { return SCENFUZZ_EGO_ABI_VERSION; }

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  driver* self;
  if (config->abi_version != SCENFUZZ_EGO_ABI_VERSION) return NULL;
  self = calloc(1, sizeof *self);
  if (self == NULL) return NULL;
  self->config = *config;
  self->comfortable_deceleration = COMFORTABLE_DECELERATION;
  if (config->vehicle.max_deceleration > 0 &&
      config->vehicle.max_deceleration < self->comfortable_deceleration) {
    self->comfortable_deceleration = config->vehicle.max_deceleration;
  }
  self->stopped_at_sign_since = NAN;
  self->last_sign_distance = INFINITY;
  return self;
}

void scenfuzz_ego_destroy(void* self) { free(self); }

/* Arc length along the route from its first point (the ego's projection) to each point. */
static void route_arc_lengths(const scenfuzz_observation* observation, double* arc) {
  uint32_t i;
  arc[0] = 0;
  for (i = 1; i < observation->route_point_count; ++i) {
    const scenfuzz_route_point* a = &observation->route[i - 1];
    const scenfuzz_route_point* b = &observation->route[i];
    arc[i] = arc[i - 1] + hypot(b->x - a->x, b->y - a->y);
  }
}

/* Front-wheel angle that makes the rear axle drive a circle through the route point about
 * `lookahead` ahead of it. */
static double pure_pursuit(const driver* self, const scenfuzz_observation* observation,
                           double lookahead) {
  const scenfuzz_ego_state* ego = &observation->ego;
  const double wheelbase =
      self->config.vehicle.wheelbase > 0 ? self->config.vehicle.wheelbase : 2.8;
  const double rear_x = ego->x - 0.5 * wheelbase * cos(ego->heading);
  const double rear_y = ego->y - 0.5 * wheelbase * sin(ego->heading);
  const scenfuzz_route_point* last = &observation->route[observation->route_point_count - 1];
  double target_x = last->x, target_y = last->y;
  double dx, dy, forward, left, distance_squared, steering;
  uint32_t i;
  int found = 0;
  for (i = 0; i < observation->route_point_count; ++i) {
    const scenfuzz_route_point* point = &observation->route[i];
    if (hypot(point->x - rear_x, point->y - rear_y) >= lookahead) {
      target_x = point->x;
      target_y = point->y;
      found = 1;
      break;
    }
  }
  if (!found) { /* the route ends closer: aim along its last heading */
    const double missing = lookahead - hypot(last->x - rear_x, last->y - rear_y);
    target_x += missing * cos(last->heading);
    target_y += missing * sin(last->heading);
  }
  dx = target_x - rear_x;
  dy = target_y - rear_y;
  forward = cos(ego->heading) * dx + sin(ego->heading) * dy;
  left = -sin(ego->heading) * dx + cos(ego->heading) * dy;
  distance_squared = forward * forward + left * left;
  if (distance_squared < 1e-6) return 0;
  steering = atan(2.0 * wheelbase * left / distance_squared);
  if (self->config.vehicle.max_steering_angle > 0) {
    steering = clamp(steering, -self->config.vehicle.max_steering_angle,
                     self->config.vehicle.max_steering_angle);
  }
  return steering;
}

/* The speed to drive now: the lowest of the limits and bend speeds ahead, each relaxed by the
 * distance there is to slow down for it. */
static double target_speed(const driver* self, const scenfuzz_observation* observation,
                           const double* arc) {
  double speed = CRUISE_SPEED_CAP;
  uint32_t i;
  if (self->config.vehicle.max_speed > 0 && self->config.vehicle.max_speed < speed) {
    speed = self->config.vehicle.max_speed;
  }
  for (i = 0; i < observation->route_point_count; ++i) {
    const scenfuzz_route_point* point = &observation->route[i];
    double limit = point->speed_limit > 0 ? point->speed_limit : CRUISE_SPEED_CAP;
    if (i + 1 < observation->route_point_count) {
      const scenfuzz_route_point* next = &observation->route[i + 1];
      const double length = arc[i + 1] - arc[i];
      if (length > 0.1) {
        const double curvature = fabs(wrap_angle(next->heading - point->heading)) / length;
        if (curvature > 1e-4) {
          const double bend_speed = sqrt(LATERAL_ACCELERATION / curvature);
          if (bend_speed < limit) limit = bend_speed;
        }
      }
    }
    limit = sqrt(limit * limit + 2.0 * self->comfortable_deceleration * arc[i]);
    if (limit < speed) speed = limit;
  }
  return speed;
}

/* Acceleration towards `speed` while keeping the time gap to something `gap` metres ahead
 * (bumper to bumper) moving at `other_speed`: the intelligent driver model. */
static double idm(const driver* self, double speed, double desired_speed, double gap,
                  double other_speed) {
  const double max_acceleration =
      self->config.vehicle.max_acceleration > 0 ? self->config.vehicle.max_acceleration : 2.0;
  const double free = desired_speed > 0.1 ? speed / desired_speed : 10.0;
  double acceleration = max_acceleration * (1.0 - free * free * free * free);
  if (isfinite(gap)) {
    const double wanted = STANDSTILL_GAP + speed * TIME_GAP +
                          speed * (speed - other_speed) /
                              (2.0 * sqrt(max_acceleration * self->comfortable_deceleration));
    const double ratio = (wanted > 0 ? wanted : 0) / (gap > 0.1 ? gap : 0.1);
    acceleration -= max_acceleration * ratio * ratio;
  }
  return acceleration;
}

/* Distance and speed along the route of the nearest object in the route's corridor ahead;
 * the distance is from the ego's front bumper to the object's rear. */
static void nearest_in_path(const driver* self, const scenfuzz_observation* observation,
                            const double* arc, double* gap, double* speed) {
  uint32_t o, i;
  *gap = INFINITY;
  *speed = 0;
  for (o = 0; o < observation->object_count; ++o) {
    const scenfuzz_object* object = &observation->objects[o];
    double best_lateral = INFINITY, along = 0, route_heading = 0;
    for (i = 0; i + 1 < observation->route_point_count; ++i) {
      const scenfuzz_route_point* a = &observation->route[i];
      const scenfuzz_route_point* b = &observation->route[i + 1];
      const double sx = b->x - a->x, sy = b->y - a->y;
      const double length_squared = sx * sx + sy * sy;
      double t = 0, lateral;
      if (length_squared > 1e-9) {
        t = clamp(((object->x - a->x) * sx + (object->y - a->y) * sy) / length_squared, 0, 1);
      }
      lateral = hypot(a->x + t * sx - object->x, a->y + t * sy - object->y);
      if (lateral < best_lateral) {
        best_lateral = lateral;
        along = arc[i] + t * (arc[i + 1] - arc[i]);
        route_heading = atan2(sy, sx);
      }
    }
    if (best_lateral <= ROUTE_CORRIDOR && along > 0) {
      const double distance = along - 0.5 * self->config.vehicle.length - 0.5 * object->length;
      if (distance < *gap) {
        *gap = distance;
        *speed = object->speed * cos(object->heading - route_heading);
      }
    }
  }
}

/* Acceleration that stops the front bumper `distance` metres ahead (from the ego's centre),
 * or +INFINITY when it does not matter yet. */
static double stop_at(const driver* self, double speed, double distance) {
  const double comfortable = self->comfortable_deceleration;
  const double room = distance - 0.5 * self->config.vehicle.length - STOP_MARGIN;
  const double needed = room > 0.01 ? speed * speed / (2.0 * room) : 1e9;
  if (!isfinite(distance)) return INFINITY;
  if (room <= 1.0) return -fmax(needed, comfortable); /* close enough: stop and stand */
  /* Brake at a constant rate once half the comfortable rate is needed; before that, approach
   * no faster than that rate can stop from. */
  if (needed >= 0.5 * comfortable) return -needed;
  return sqrt(comfortable * room) - speed;
}

/* The stop sign's line to stop at, or INFINITY once the ego has stood there long enough. */
static double stop_sign_line(driver* self, const scenfuzz_observation* observation) {
  const double distance = observation->stop_sign_distance;
  const double room = distance - 0.5 * self->config.vehicle.length - STOP_MARGIN;
  /* A line farther away than the one just passed is the next sign. */
  if (!isfinite(distance) || distance > self->last_sign_distance + 5.0) {
    self->sign_cleared = 0;
    self->stopped_at_sign_since = NAN;
  }
  self->last_sign_distance = distance;
  if (!isfinite(distance) || self->sign_cleared) return INFINITY;
  if (room < 1.5 && observation->ego.speed < 0.1) {
    if (isnan(self->stopped_at_sign_since)) self->stopped_at_sign_since = observation->ego.time;
    if (observation->ego.time - self->stopped_at_sign_since >= STOP_SIGN_WAIT) {
      self->sign_cleared = 1;
      return INFINITY;
    }
  }
  return distance;
}

/* The indicator towards the sharpest turn of the route within the indicating distance ahead. */
static uint32_t turn_indicator(const scenfuzz_observation* observation, const double* arc) {
  const double notice = fmax(INDICATE_DISTANCE, INDICATE_TIME * observation->ego.speed);
  const double heading = observation->route[0].heading;
  double sharpest = 0;
  uint32_t i;
  for (i = 1; i < observation->route_point_count && arc[i] <= notice; ++i) {
    const double turn = wrap_angle(observation->route[i].heading - heading);
    if (fabs(turn) > fabs(sharpest)) sharpest = turn;
  }
  if (sharpest > TURN_ANGLE) return SCENFUZZ_SIGNAL_LEFT_INDICATOR;
  if (sharpest < -TURN_ANGLE) return SCENFUZZ_SIGNAL_RIGHT_INDICATOR;
  return 0;
}

/* The lights and wipers the weather and the time of day ask for. */
static uint32_t weather_signals(const scenfuzz_environment* environment) {
  uint32_t signals = 0;
  if (environment->darkness > 0 || environment->fog >= THICK_FOG)
    signals |= SCENFUZZ_SIGNAL_LOW_BEAM;
  if (environment->fog >= THICK_FOG) signals |= SCENFUZZ_SIGNAL_FOG_LIGHTS;
  if (environment->rain > 0 || environment->snow > 0) signals |= SCENFUZZ_SIGNAL_WIPERS;
  return signals;
}

int scenfuzz_ego_step(void* state, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  driver* self = state;
  const double speed = observation->ego.speed;
  double arc[SCENFUZZ_ROUTE_POINTS];
  double acceleration, gap, other_speed, stop;
  double max_deceleration =
      self->config.vehicle.max_deceleration > 0 ? self->config.vehicle.max_deceleration : 6.0;
  double max_acceleration =
      self->config.vehicle.max_acceleration > 0 ? self->config.vehicle.max_acceleration : 2.0;

  control->version = SCENFUZZ_EGO_ABI_VERSION;
  control->signals = weather_signals(&observation->environment);
  if (observation->route_point_count == 0) { /* nowhere to go: stop */
    control->acceleration = -self->comfortable_deceleration;
    control->steering_angle = 0;
    return 0;
  }
  route_arc_lengths(observation, arc);
  control->signals |= turn_indicator(observation, arc);
  control->steering_angle = pure_pursuit(self, observation, fmax(5.0, 0.8 * speed));

  nearest_in_path(self, observation, arc, &gap, &other_speed);
  acceleration = idm(self, speed, target_speed(self, observation, arc), gap, other_speed);

  stop = stop_sign_line(self, observation);
  if (observation->light == SCENFUZZ_LIGHT_RED) {
    stop = fmin(stop, observation->light_distance);
  } else if (observation->light == SCENFUZZ_LIGHT_YELLOW) {
    /* Stop for yellow only when it takes no more than a firm, not a full, brake. */
    const double room =
        observation->light_distance - 0.5 * self->config.vehicle.length - STOP_MARGIN;
    if (room > 0 && speed * speed / (2.0 * room) <= 0.6 * max_deceleration) {
      stop = fmin(stop, observation->light_distance);
    }
  }
  stop = fmin(stop, observation->distance_to_target + 0.5 * self->config.vehicle.length +
                        STOP_MARGIN); /* the target is where the centre stops */
  if (!isfinite(observation->distance_to_target) &&
      observation->route_point_count < SCENFUZZ_ROUTE_POINTS) {
    /* No target, and the lanes end within sight: stop the front bumper at their end. (With a
     * target the route ends there, and the target stop above already places the centre.) */
    stop = fmin(stop, arc[observation->route_point_count - 1]);
  }
  acceleration = fmin(acceleration, stop_at(self, speed, stop));

  control->acceleration = clamp(acceleration, -max_deceleration, max_acceleration);
  return 0;
}
