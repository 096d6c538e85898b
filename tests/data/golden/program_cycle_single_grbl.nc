; ProbeCycle program for grbl: the tuned cycle.
; One surface touched with the scenario's strategy, feeds, backoff and start
; distance: a plain skip sequence, no macro call.
; Every probing move searches past the farthest place its surface can be by
; more than the touch's stop (cycle.search_beyond_mm), and every later one
; covers the whole move back before it: the axis is never braking for the
; move's end when it touches.
; Plan eeb518b603110ff8 (keep the plan file: the import matches the positions to it).
; Date 2026-01-15.
; Scenario values and options used:
;   machine.accel_model = time_constant
;   machine.time_constant_s = 0.06
;   machine.max_accel_mm_s2 = 2000
;   machine.max_jerk_mm_s3 = 40000
;   machine.filter = none
;   machine.filter_time_s = 0.03
;   machine.servo_time_constant_s = 0
;   machine.scan_period_s = 0.004
;   machine.controller_latency_s = 0.002
;   probe.interface_delay_s = 0.002
;   probe.pretravel_mm = 0.005
;   probe.overtravel_limit_mm = 5
;   cycle.feed_override_max_pct = 120
;   cycle.strategy = single_touch
;   cycle.approach_mm = 5
;   cycle.probe_feed_mm_min = 300
;   cycle.measure_feed_mm_min = 30
;   cycle.backoff_mm = 2
;   cycle.backoff_from = stop
;   cycle.return_feed_mm_min = 10000
;   ball_diameter_mm = 0
;   point_uncertainty_mm = 0.012083
;   independent_uncertainty_mm = 0.011818
;   probe.artefact_uncertainty_mm = 0.001
;   machine.thermal_drift_mm = 0.002
; WARNING: prove this program out first at reduced feed override (every
; move runs at a feed, none at the rapid), with the probe clear of the
; part, and check every move against your machine before a touch.
; Every move is incremental (G91) from where the probe stands when the program
; starts or a pause ends. A probing move that does not trigger stops the
; program.
; Positions: grbl answers [PRB:x,y,z:1] after each probe (machine
; positions; set $13=0 for mm). Save the sender's console to a file and
; import that file.
; grbl has no variables or arithmetic: the program computes nothing and
; checks no tolerance. probecycle import computes the feature's result
; (and the tolerance check) from the console's [PRB:] lines.
G21 G91 G94
; check: the probe stands 5 mm in front of the surface, touching along X+; resume to start
M0
; Plan signature (plan eeb518b603110ff8): twice, G38.3 out along Z+ and back; grbl's
; [PRB:...:0] answers tell the import which plan ran. Free air needed: 1.000 mm along Z+.
G38.3 Z1.000 F300
G38.3 Z-0.900 F300
G1 Z-0.100 F300
G38.3 Z0.380 F300
G38.3 Z-0.280 F300
G1 Z-0.100 F300
; touch 1: X+ at 300 mm/min
G38.2 X7.617 F300
G1 X-5.195 F10000 ; back to the start
G90
M2
