# A sandstorm at a village crossing: visibility falls to a few tens of metres, a woman crosses
# the road and a cyclist rides ahead of the car.
import from MAP
  length: 500
  width: 40
RoadNetwork
  road → name village_road
    left boundary: (0.0, 23.5) (500.0, 23.5)
    center lines: (0.0, 20.0) (500.0, 20.0)
    right boundary: (0.0, 16.5) (500.0, 16.5)
Weather
  cloudiness: 0.6
  wetness: 0.0
  precipitation: 0.0
  wind_intensity: 0.9
  visibility: 0.2
NaturalDisaster
  MeteorologicalDisaster
    sandstorm: 1
Entity
  DynamicEntity1
    name: ego
    timestamp: 2023-04-02 15:10:00
    speed: 20.0
    acceleration: 0.0
    track: to the east
    position: (30.0, 18.2)
  DynamicEntity2
    name: cyclist
    timestamp: 2023-04-02 15:10:00
    speed: 15.0
    acceleration: 0.0
    track: ahead
    position: (90.0, 17.6)
  DynamicEntity3
    name: woman
    timestamp: 2023-04-02 15:10:00
    speed: 4.5
    acceleration: 0.0
    track: crosses the road
    position: (140.0, 15.8)
ConstraintList
  safety_protocol: (lighton = true) && (foglighton = true)
  constraint1 relate with ego, woman
    safety_protocol: not (speed > 35)
