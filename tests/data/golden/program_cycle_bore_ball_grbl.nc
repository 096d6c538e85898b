; ProbeCycle program for grbl: the tuned cycle on a bore.
; X+, X-, Y+ and Y- touched with the scenario's strategy, feeds, backoff and
; start distance, from the centre at the measuring depth: a protected move
; out to each touch's start and back to the centre.
; Every probing move searches past the farthest place its surface can be by
; more than the touch's stop (cycle.search_beyond_mm), and every later one
; covers the whole move back before it: the axis is never braking for the
; move's end when it touches.
; Plan 9f3fb1d6cfe88929 (keep the plan file: the import matches the positions to it).
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
;   cycle.strategy = two_touch
;   cycle.approach_mm = 5
;   cycle.probe_feed_mm_min = 2000
;   cycle.measure_feed_mm_min = 30
;   cycle.backoff_mm = 2
;   cycle.backoff_from = stop
;   cycle.return_feed_mm_min = 10000
;   cycle.feature = bore
;   cycle.feature_size_mm = 50
;   cycle.position_feed_mm_min = 3000
;   ball_diameter_mm = 6
;   point_uncertainty_mm = 0.003742
;   independent_uncertainty_mm = 0.002769
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
; Protected moves are G38.3, the probe armed: grbl answers [PRB:...:0] after
; one that touches nothing. It stops one that touches something ([PRB:...:1])
; but cannot branch, so the program goes on; the next G38.2 or G38.3 then
; stops it with ALARM:4 if the probe is still deflected. No probe follows the
; last protected move: the import refuses a console where one answers :1.
; grbl has no variables or arithmetic: the program computes nothing and
; checks no tolerance. probecycle import computes the feature's result
; (and the tolerance check) from the console's [PRB:] lines.
G21 G91 G94
; check: the probe ball stands at the centre of the bore at the measuring depth; resume to start
M0
; Plan signature (plan 9f3fb1d6cfe88929): twice, G38.3 out along Z+ and back; grbl's
; [PRB:...:0] answers tell the import which plan ran. Free air needed: 0.870 mm along Z+.
G38.3 Z0.680 F300
G38.3 Z-0.580 F300
G1 Z-0.100 F300
G38.3 Z0.870 F300
G38.3 Z-0.770 F300
G1 Z-0.100 F300
; out to the start of the X+ touch
G38.3 X20.000 F3000
; X+ first touch at 2000 mm/min
G38.2 X8.263 F2000
G1 X-2.000 F10000 ; backoff
; touch 1: X+ measuring touch at 30 mm/min
G38.2 X4.514 F30
G1 X-5.024 F10000 ; back to the start
; back to the centre
G38.3 X-20.000 F3000
; out to the start of the X- touch
G38.3 X-20.000 F3000
; X- first touch at 2000 mm/min
G38.2 X-8.263 F2000
G1 X2.000 F10000 ; backoff
; touch 2: X- measuring touch at 30 mm/min
G38.2 X-4.514 F30
G1 X5.024 F10000 ; back to the start
; back to the centre
G38.3 X20.000 F3000
; out to the start of the Y+ touch
G38.3 Y20.000 F3000
; Y+ first touch at 2000 mm/min
G38.2 Y8.263 F2000
G1 Y-2.000 F10000 ; backoff
; touch 3: Y+ measuring touch at 30 mm/min
G38.2 Y4.514 F30
G1 Y-5.024 F10000 ; back to the start
; back to the centre
G38.3 Y-20.000 F3000
; out to the start of the Y- touch
G38.3 Y-20.000 F3000
; Y- first touch at 2000 mm/min
G38.2 Y-8.263 F2000
G1 Y2.000 F10000 ; backoff
; touch 4: Y- measuring touch at 30 mm/min
G38.2 Y-4.514 F30
G1 Y5.024 F10000 ; back to the start
; back to the centre
G38.3 Y20.000 F3000
G90
M2
