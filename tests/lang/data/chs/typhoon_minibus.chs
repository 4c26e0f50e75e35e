# The grammar's worked example: a minibus on a narrow road in a typhoon.
import from MAP
  length: 400
  width: 50
RoadNetwork
  road → name narrow_road
    left boundary: (0.0, 50.0) (400.0, 50.0)
    center lines: (0.0, 25.0) (400.0, 25.0)
    right boundary: (0.0, 0.0)
                    (400.0, 0.0)
Weather
  cloudiness: 1.0
  wetness: 1.0
  air_pressure: 1.0
  precipitation: 1.0
  wind_intensity: 1.0
  visibility: 0.4
NaturalDisaster
  MeteorologicalDisaster
    rainstorm: 0
    sandstorm: 0
    typhoon: 1
    tornado: 0
  GeologicalDisaster
    debrisflow: 0
    landslide: 0
    collapse: 0
SpecialHighRisk
  rough: 0
  iceRoad: 0
  steepDescentAhead: 1
  muddy: 0
  wade: 1
Entity
  StaticEntity1
    name: pedestrians
    overview: little boy
  StaticEntity2
    name: traffic_light
    overview: red light
  DynamicEntity1
    name: minibus
    timestamp: 2022 年 1 月 30 日 17:30:42
    speed: 45.0
    acceleration: 0.0
    track: curve to the east
    aim: The First People's Hospital
ConstraintList
  constraint1 relate with forward_vehicle, current_vehicle
    safety_protocol: (wiper = true) && (lighton = true) && (hazardlighton = true)
    event: when guard do action
    action: position++
    guard: first_car_parked == false || second_car_parked == false
    probability: 0.2
  constraint2 relate with currentvehicle, edge
    safety_protocol: ((dist > safedistance) = true) && (emergencybreak = false)
    event: when guard do action
    action: parked = false
    guard: wait > 5
    probability: 0.8
