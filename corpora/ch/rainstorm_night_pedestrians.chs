# A rainstorm at night in a town: two people cross the road ahead of the car, one from each side
# of a parked van that hides them.
import from MAP
  length: 500
  width: 40
RoadNetwork
  road → name town_street
    left boundary: (0.0, 24.0) (500.0, 24.0)
    center lines: (0.0, 20.0) (500.0, 20.0)
    right boundary: (0.0, 16.0) (500.0, 16.0)
Weather
  cloudiness: 1.0
  wetness: 1.0
  precipitation: 1.0
  wind_intensity: 0.6
  visibility: 0.6
NaturalDisaster
  MeteorologicalDisaster
    rainstorm: 1
Entity
  StaticEntity1
    name: parked_van
    overview: a van parked at the kerb
    position: (118.0, 16.9)
  DynamicEntity1
    name: car
    timestamp: 2023-06-18 22:40:00
    speed: 30.0
    acceleration: 0.0
    track: straight to the east
    position: (40.0, 18.0)
  DynamicEntity2
    name: man
    timestamp: 2023-06-18 22:40:00
    speed: 5.0
    acceleration: 0.0
    track: crossing
    position: (126.0, 15.4)
  DynamicEntity3
    name: girl
    timestamp: 2023-06-18 22:40:00
    speed: 4.0
    acceleration: 0.0
    track: crossing
    position: (150.0, 24.6)
ConstraintList
  safety_protocol: (wiper = true) && (lighton = true)
