# A rainstorm at a signalised crossroads at dusk: the light is red for the car as it comes up, a
# truck ahead turns right, an oncoming taxi turns left across the car's path once the light
# changes (giving way to the car first), and a cyclist rides north on the crossing street.
import from MAP
  length: 400
  width: 400
RoadNetwork
  road → name avenue
    left boundary: (0.0, 207.0) (400.0, 207.0)
    center lines: (0.0, 200.0) (400.0, 200.0)
    right boundary: (0.0, 193.0) (400.0, 193.0)
  road → name market_street
    left boundary: (196.5, 0.0) (196.5, 400.0)
    center lines: (200.0, 0.0) (200.0, 400.0)
    right boundary: (203.5, 0.0) (203.5, 400.0)
Weather
  cloudiness: 1.0
  wetness: 0.9
  precipitation: 0.8
  wind_intensity: 0.5
  visibility: 0.5
NaturalDisaster
  MeteorologicalDisaster
    rainstorm: 1
Entity
  DynamicEntity1
    name: car
    timestamp: 2023-07-14 19:20:00
    speed: 40.0
    acceleration: 0.0
    track: to the east
    position: (100.0, 198.3)
  DynamicEntity2
    name: truck
    timestamp: 2023-07-14 19:20:00
    speed: 30.0
    acceleration: 0.0
    track: turn right
    position: (140.0, 194.8)
  DynamicEntity3
    name: taxi
    timestamp: 2023-07-14 19:20:00
    speed: 35.0
    acceleration: 0.0
    track: oncoming, turn left
    position: (300.0, 201.7)
  DynamicEntity4
    name: cyclist
    timestamp: 2023-07-14 19:20:00
    speed: 15.0
    acceleration: 0.0
    track: north
    position: (201.8, 120.0)
  StaticEntity1
    name: traffic light
    overview: the light is red as the car comes up
ConstraintList
  safety_protocol: (wiper = true) && (lighton = true)
  constraint1 relate with car, taxi
    safety_protocol: not (speed > 40)
