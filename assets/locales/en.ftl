### zieglerlab: the window's words in English, the source language.
###
### Every other language's file has the same messages, with the same
### placeables ({ $name }); the tests check both. Numbers reach these
### messages already written, with a decimal point, so that they read as
### the command line prints them. Counts ($count) select plural forms.
###
### Glossary (the terms every language's file keeps the same everywhere):
###   flutter: a swing that grows (dynamic instability)
###   divergence: bending away without swinging (static instability)
###   follower force; dead load; critical load; root locus; eigenvalue;
###   growth rate; damping; limit cycle; Hopf bifurcation (soft / hard
###   onset); rod; column; spring; roller; moving band; friction;
###   stability map; Ziegler's paradox

## Counts

rods-count = { $count ->
    [one] { $count } rod
   *[other] { $count } rods
}

## The sidebar's heading and its menus

menu-share = share
    .tooltip = the settings as text: copy them, or paste some
menu-record = record
    .tooltip = record the window to a GIF
menu-keys = keys
    .tooltip = the keyboard's commands
menu-language = the window's language (remembered for the next launch)
    .name = language: { $language }
projector-toggle = projector (P)
overlay = overlay
    .none = none
    .tooltip = another model's locus in grey, at the same a (as Fig. 8 sets the ideal column beside the roller)
section-parameters = parameters

## The status line at the window's foot

status-dismiss = dismiss
    .tooltip = clear this message
status-latest = the latest message (the whole text)
status-got-it = got it
    .tooltip = hide the hint
status-ready = ready
hint-first-launch = Drag the load bar to about 3 and press K to kick the column (space pauses).

## The tabs

tab-locus = root locus
    .tooltip = the root locus: the column's eigenvalues in the complex plane and against the load. Left of the vertical axis a motion dies away, right of it it grows; the height is the frequency. Flutter starts where a pair crosses the axis
tab-histories = time histories
    .tooltip = the angles, the energy and the band's power over the run
tab-map = stability map
    .tooltip = the stability of every load against a second parameter
tab-paradox = paradox
    .tooltip = the first critical load as the damping (or the roller's mass) vanishes
tab-post-critical = post-critical
    .tooltip = past the flutter onset: the limit cycles' size against the load, stable or not, and the running column's own swing
save-png = save PNG...
    .tooltip = these plots as a picture, without the buttons and hints
save-csv = save CSV...
    .tooltip = the numbers behind these plots, in the command line's columns, to a file
answer-hidden = This plot shows the answer: it comes back when the lesson reveals it.
answer-hidden-histories = { answer-hidden } The time histories show what the column does.
tab-in-column-place = The { $tab } tab shows in the column's place; the root locus tab brings the column back.
locus-beside-column = The root locus is beside the column; a tab chosen here shows in the column's place.
plots-need-room = The plots need more room here: a taller window, or projector mode off (P).

## The welcome of a first launch

welcome-title = Welcome to zieglerlab
welcome-column = Two rods on springs stand clamped at one end. At the other end a force pushes along the last rod and turns with it: a follower force. Here it is made as in the laboratory, by a roller that a moving band drags along.
welcome-states = At small loads a nudge swings and stays small: the column is stable. Past a critical load it flutters: it swings back and forth, wider and wider. At larger loads still it can diverge: it bends away to one side without swinging.
welcome-locus = The root locus draws how the column moves as numbers (its eigenvalues) while the load grows. Left of the vertical axis a swing dies away; right of it, it grows. How far right is the growth rate, how high up the frequency.
welcome-try = Drag the load bar and watch both: the column starts to flutter at the load where the eigenvalues cross the axis.
welcome-first-lesson = start the first lesson
    .tooltip = a few steps: predict where flutter starts, then watch
welcome-explore = explore on my own
    .tooltip = close this; the lessons stay at the top of the sidebar

## States and critical loads

state-stable = stable
state-flutter = flutter
state-divergence = divergence
transition = p = { $load }: { $from } -> { $to }
transition-meaning = p = { $load }: the column goes from { $from } to { $to }; { $how }
    .to-flutter = past this load a pair of eigenvalues lies right of the imaginary axis: a kick grows into a growing swing
    .to-divergence = past this load a real eigenvalue is positive: the column leans away without swinging
    .to-stable = past this load no eigenvalue lies right of the imaginary axis: a kick no longer grows
duration-forever = forever
duration-days = { $count ->
    [one] { $n } day
   *[other] { $n } days
}
duration-years = { $count ->
    [one] { $n } year
   *[other] { $n } years
}

## The model and the engine

model = model
    .source = { $source }: where the model is in the study this program follows (its figure and equations)
preset-ziegler-1952 = Ziegler 1952
    .description = Ziegler's column: massless rods, point mass 2m at the joint A and m at the tip, ideal follower force
preset-uniform-rods = Fig. 1a
    .description = Uniform rigid rods of mass m (Fig. 1a), ideal follower force
preset-midpoint-masses = Fig. 1b, eqs 1-7
    .description = Massless rods with a point mass m at each midpoint (Fig. 1b, eqs 1-7), ideal follower force
preset-roller = Fig. 7, eqs 8-38
    .description = Uniform rods with a roller dragged by a moving band (Fig. 7, eqs 8-38), consistent spin inertia; Fig. 8 parameters
preset-roller-as-printed = eq. 39, Fig. 8
    .description = The roller model as printed in eq. (39): the spin inertia multiplied by r/l2, an erratum of the paper; Fig. 8 parameters
preset-tabletop = lecture pace
    .description = A desk-sized column for a lecture: uniform rods of 25 cm and 100 g, springs of 0.0625 N m/rad (a = 10 1/s^2), ideal follower force; past p = 2.54 it flutters with a period of about 1.5 s
preset-tabletop-roller = lecture pace
    .description = The tabletop column pushed by a 10 g roller of radius 2.5 cm on a band at 0.1 m/s (nu = rho = mu = 0.1): a weak flutter from p = 0.024 that takes minutes to grow, a strong one near the ideal column's load
preset-beck = Beck 1952, a chain of 16 rods
    .description = Beck's column as a chain of 16 uniform rods with springs k at every joint (a beam of EI = k l, L = 16 l), follower force: flutter at P L^2/EI = 18.78 (Beck's continuous column: 20.05)
preset-pflueger = Pflueger's column, a chain of 16 rods
    .description = Pflueger's column: Beck's chain of 16 rods with a tip mass of half the column's mass, follower force: the tip mass lowers the flutter load to P L^2/EI = 15.06
preset-beck-roller = Beck's chain loaded as in Bigoni et al. 2018
    .description = Beck's chain of 16 rods loaded by the roller on the moving band (the paper's groups on each rod: roller mass 0.1 m, radius 0.1 l, mu = 0.1, V = 0.1 m/s): the slip's damping makes it flutter weakly from P L^2/EI = 0.025 (growth below 3e-4 1/s), and strongly from about 18.8, where the follower chain flutters
preset-pflueger-roller = Pflueger's chain loaded as in Bigoni et al. 2018
    .description = Pflueger's chain of 16 rods (tip mass half the rods' mass) loaded by the same roller on the moving band: weak flutter from P L^2/EI = 0.008 (growth below 4e-5 1/s), strong flutter from 15.06, where the follower chain flutters
tip-force-dead = tip force: a dead load (eta = 0), fixed in direction, in place of the preset's follower force
tip-force-partial = tip force: partly tangential, turned by eta = { $eta } of the last rod's angle (the preset's follower force has eta = 1)
engine = engine
    .tooltip = what integrates the motion: the run goes on from where it is
engine-rapier = rapier
    .tooltip = rapier: the rapier2d physics engine, rods as rigid bodies joined by hinges (a multibody), the roller's spin implicit
engine-reference = reference
    .tooltip = adaptive Dormand-Prince 5(4) on the exact equations

## The load

load-field = load p = P l/k
    .tooltip = type a load (Enter applies, Escape restores); beyond the bar's end too
    .meaning = the load without units: the tip force P times the rod's length l over the springs' stiffness k (Ziegler's column flutters from p = 2.09)
roller-load = roller: q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = the roller's own load: the force R pressing it on the band, in the units of p; the band's friction pushes with μ R, so p = μ q
notes-more = ... and { $count } more (hover)
load-beyond-range = p = { $load } is beyond the plotted range (0 to { $end }); the status below is at p
critical-loads-hidden = The critical loads are hidden until the lesson reveals them.
not-resolved = the stability is not resolved here (hover for why)
ramp-visible = the tip off by { $percent }% of the length
ramp-theory = theory (white mark): unstable from p = { $load }
ramp-seen = seen (mark): motion visible at p = { $load } ({ $visible })
ramp-seen-late = seen (mark): motion visible at p = { $load }, late: hover for why ({ $visible })
    .why = It shows late: past the onset the motion needs time to grow to a visible size, and the ramp moves on meanwhile. A slower ramp shows it closer to the theory.
ramp-watching = watching for the motion to become visible ({ $visible })

## The parameters

groups = dimensionless groups
    .tooltip = the few combinations of the SI values that decide the motion (a = k/(m l^2) sets how fast it is; the roller's nu, rho, mu and V its mass, size, friction and the band's speed); changing one keeps the others
si-parameters = SI parameters
mu-moves-load = (R held: moves p)
key-allowed = { $description } (allowed: { $range })
refused = refused: { $why }
key-load = load p = P l/k on the common axis (P = mu R for the roller; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2): sets k1 (and k2 in the same ratio), keeps p
    .range = > 0
key-nu = nu = m3/m, roller mass over the rod's mass
    .range = >= 0
key-rho = rho = r/l, roller radius over the rod's length
    .range = in (0, l2/l]
key-mu = friction coefficient; only mu R enters the equations, so R is held and the load p = mu R l/k moves
    .range = > 0
key-V = band speed (the band moves toward -x); the linear analysis needs V > 0
    .range = >= 0
key-l1 = length of rod 1 (its mass distribution scales with it)
    .range = > 0
key-l2 = length of rod 2 (its mass distribution scales with it)
    .range = > 0
key-m1 = mass of rod 1, point masses on it included (distribution kept)
    .range = >= 0
key-m2 = mass of rod 2 (distribution kept)
    .range = >= 0
key-s1 = centre of mass of rod 1, from the clamp O
    .range = in [0, l1]
key-s2 = centre of mass of rod 2, from the joint A
    .range = in [0, l2]
key-I1 = moment of inertia of rod 1 about its centre of mass
    .range = >= 0
key-I2 = moment of inertia of rod 2 about its centre of mass
    .range = >= 0
key-m_tip = point mass at the tip B (the roller's mass is m3)
    .range = >= 0
key-k1 = rotary spring at the clamp O
    .range = > 0
key-k2 = rotary spring at the joint A
    .range = > 0
key-c1 = viscous damper at the clamp O
    .range = >= 0
key-c2 = viscous damper at the joint A
    .range = >= 0
key-c_ext = external viscous drag along both rods (air drag, linearized): a force per unit length of c_ext times the local velocity across the rod
    .range = >= 0
key-rods = rods in the chain: rod 1, then copies of rod 2 with joint A's spring and damper at every joint; the tip mass and load at the last rod's end
    .range = from 2 to 64
key-P = magnitude of the tip force
    .range = >= 0
key-eta = tangency of the tip force: its direction turns by eta times the last rod's angle (1: follower force, 0: dead load)
    .range = in [0, 1]
key-m3 = mass of the roller (0: massless, the ideal follower force)
    .range = >= 0
key-r = radius of the roller
    .range = in (0, l2]
key-R = normal force of the roller on the band
    .range = >= 0

## Time

command-play = play
    .running = pause
    .tooltip = play / pause
command-load-up = load up
    .tooltip = load up by a hundredth of the load bar
command-load-down = load down
    .tooltip = load down by a hundredth of the load bar
command-kick = kick
    .tooltip = kick: every rod turned by 0.03 rad
command-reset = reset
    .tooltip = reset: a fresh run from the standard perturbation
command-reset-all = reset all
    .tooltip = reset all: the preset's parameters and load, normal speed, a fresh run, the default views; an open lesson is closed
command-projector = projector mode
    .tooltip = projector mode: high contrast, large text
command-next = next
    .tooltip = the lesson's next step (a presenter's remote sends Page Down)
command-back = back
    .tooltip = the lesson's previous step (Page Up)
command-full-screen = full screen
    .tooltip = full screen: the window fills the screen (again to leave)
command-step = step
    .tooltip = one engine step (1/240 s), then paused
key-space = space
key-right = right
key-up = up
key-left = left
key-down = down
key-page-down = page down
key-page-up = page up
focus-keys-tab = the next control (shift+tab: the previous one)
    .keys = tab
focus-keys-ctrl-tab = the next tab (ctrl+shift+tab: the previous one)
    .keys = ctrl+tab
focus-keys-press = with a button, checkbox, choice or tab focused: press it (space plays only with nothing focused)
    .keys = space, enter
focus-keys-slider = with a slider focused (the load bar, the prediction): move it by a hundredth; shift: a tenth
    .keys = left, right
focus-keys-column = with the column focused (tab to it): turn it by 0.02 rad either way, shift: 0.1 rad (the keyboard's drag)
    .keys = left, right
focus-keys-ends = with the load bar or the prediction focused: its ends
    .keys = home, end
focus-keys-plot = with a plot focused (tab to it): pan by a tenth, zoom about the centre; enter: a map takes the cell under the cross
    .keys = arrows, +, -
focus-keys-escape = let go of the focus (a text field: undo the typing)
    .keys = esc
focus-keys-others = page down, page up, K, R, P and up/down work whatever is focused, but a text field being edited
    .keys = the others
pace-slow = Slow
    .tooltip = a quarter of real time
pace-normal = Normal
    .tooltip = real time: one simulated second per second
pace-fast = Fast
    .tooltip = four times real time
speed-factor = × speed
    .tooltip = simulated seconds per second of wall-clock time
run-time = t = { $secs } s   ({ $status })
run-paused = paused
run-running = running
run-diverged = diverged at t = { $secs } s
run-too-stiff = too stiff for the reference integrator at t = { $secs } s: a very light roller or a stopped band (the rapier engine handles those), or a load or stiffness so large that no step resolves the column's rates
run-too-fast = too fast for the rapier engine at t = { $secs } s: the column turns at { $rate } rad/s, more than its fixed step resolves ({ $most } rad per step); the reference engine follows it
run-lagging = running at { $achieved }x: this computer cannot keep up at { $asked }x

## The status card

card-stable =
    .meaning = stable: a small nudge stays small (it dies away, or with no damping at all keeps its size)
card-flutter =
    .meaning = flutter: the column swings back and forth, wider and wider (a pair of eigenvalues right of the axis)
card-divergence =
    .meaning = divergence: the column bends away to one side without swinging (a real eigenvalue right of the axis)
card-weak-flutter = weak flutter
    .meaning = weak flutter: the swing grows, but by less than 1% of its frequency: slowly, over many swings
card-hidden = stable or not?
    .why = The verdict is hidden until the lesson reveals it: watch the column.
card-no-figures = no stability figures: { $why }
card-growth = growth rate  { $rate } 1/s
    .tooltip = growth rate: how fast the motion grows (positive) or dies away (negative), per second: the real part of the eigenvalue furthest right
card-growth-zero = growth rate  0 (to within { $tolerance } 1/s)
card-not-resolved = not resolved at these parameters: see the warning under the load
card-e-folding = e-folding time  { $time }
    .tooltip = e-folding time: the time in which the swing grows by a factor e = 2.72 (1 / growth rate)
card-decay = decay time  { $time }
    .tooltip = decay time: the time in which the swing shrinks by a factor e = 2.72
card-neutral = neutral: no growth, no decay
card-mode = mode { $k } of { $n }
card-the-mode = the mode
card-frequency = frequency  { $frequency } rad/s  (period { $period } s{ $which })
    .tooltip = frequency: how fast the column swings, in radians per second (the eigenvalue's height); the period is one full swing. A column of n rods has n modes of swinging, counted here from the slowest; the card describes the one that grows fastest (or dies away slowest), and the run's measurement is shown for that same mode
card-non-oscillatory = non-oscillatory: the dominant eigenvalue is real
card-measured = measured from the run{ $mode }  { $measurement }
    .tooltip = the eigenvalue fitted to the run's own motion (a matrix pencil of the angles): at least 20 s of small swings (below 0.05 rad) since the last kick, release or change, each mode once the run holds a whole period of it; 'mode 2 of 2' counts the column's modes of swinging from the slowest. The ± is the fit's own uncertainty: how far fits over the run's first and last three quarters fall from the whole run's. The engine's time step dt moves the run itself from the linear model too, its frequency by about ω³dt²/24
card-measured-other-mode = measured from the run: { $mode } only, { $measurement } (the card's { $card } too weak in this run to fit)
card-measured-other = measured from the run: another eigenvalue only, { $measurement } (the card's too weak in this run to fit)
card-measured-after = measured: after 20 s of small-amplitude motion (|φ| < 0.05 rad)
card-measured-two-rods = measured: for two rods only (a chain's many slow modes need a longer run than a fit can use)
card-measurement = growth { $growth } 1/s, frequency { $frequency } rad/s
card-measurement-unknown = growth { $growth } 1/s, frequency { $frequency } rad/s (uncertainty unknown: too few periods in the run)
card-grows-slowly = grows by { $percent } per period: watch for minutes, not seconds
card-grows-too-slowly = grows by { $percent } per period: too slow to see in a lesson
onset-soft = soft onset at p = { $at }: the swing settles on a limit cycle that grows from zero
onset-soft-roller = soft onset at p = { $at }: a cycle grows from zero, until the roller nears sticking
onset-hard = hard onset at p = { $at }: the swing jumps to a large cycle, which persists below the onset
onset-degenerate = onset at p = { $at } neither soft nor hard to first order
onset-reversible = no damping: no limit cycle to settle on (a reversible column)
    .tooltip = Without damping the column is reversible: flutter starts where two pairs of eigenvalues meet on the imaginary axis, and there is no attractor, so no limit cycle the swing could settle on.
onset =
    .tooltip = Soft: past the onset the swing grows from zero to a small steady cycle, larger as the load rises; hard: it jumps to a large one, which stays when the load is lowered a little. Sticking: the roller stops slipping on the band, where the friction changes its law.{"\u000A"}{"\u000A"}First Lyapunov coefficient { $lyapunov } at the onset p = { $at } (Hopf point, frequency { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = Near it the cycle's |phi1| is about { $a } sqrt(p - { $at }) rad.
onset-sticking = On the roller the slip at the contact falls as the cycle grows; where it nears zero the friction is no longer smooth and the motion turns to stick-slip, which this analysis does not follow: the post-critical tab's branch ends there.

## The load ramp

ramp = ramp the load
ramp-from = from
    .name = ramp from
    .tooltip = the load the ramp starts at
ramp-to = to
    .name = ramp to
    .tooltip = the load the ramp stops at
ramp-rate = at
    .name = ramp rate
    .tooltip = how fast the load moves, per simulated second
ramp-start = start ramp
    .tooltip = the load goes to 'from' and moves to 'to' at the rate, as the run goes on (setting the load by hand ends it)
ramp-pause = pause ramp
    .tooltip = hold the load where it is; the run goes on
ramp-resume = resume
ramp-stop = stop
    .tooltip = end the ramp
ramp-done = done
ramp-paused = paused
ramp-moving = moving
ramp-progress = p = { $load } toward { $to } at { $rate }/s ({ $doing })

## Sharing the settings

share-copy = copy settings
    .tooltip = the model, load, engine and speed as text, to the clipboard and the box below
share-paste = paste from clipboard
    .tooltip = take settings text copied elsewhere (the box below shows it)
share-box = or type or paste settings text here
share-take = take the text above
    .tooltip = load the settings written in the box
paste-too-long = paste refused, nothing changed: the text holds { $bytes } bytes; no field here takes more than { $most } (settings text is under 2000)
paste-no-text = paste settings: the clipboard holds no text (copy the settings text first)

## Lessons

lessons = lessons
lessons-built-in = the built-in lesson { $name }
lesson-file = lesson file
    .hint = a lesson file (.ron)
    .tooltip = the path of your own lesson file (see the README for the format)
lesson-open = open
    .tooltip = read and check the file, then start it
lesson-reading = reading { $path }
lesson-reading-stopped = { $path }: the reading stopped without an answer
lesson-step = step { $k } of { $n }
lesson-prediction = your prediction: p = { $load }
lesson-predicted-load = predicted load
    .tooltip = where you expect it; the load bar marks it (keys as on the load bar: left, right, shift for ten steps, home, end)
lesson-back = back
    .tooltip = the previous step (Page Up)
lesson-next = next
    .tooltip = the next step: it sets and starts what it says (Page Down, as a presenter's remote sends)
lesson-close = close lesson
    .tooltip = leave the lesson; the model stays as it is
lesson-next-lesson = next lesson: { $title }
    .tooltip = open the next lesson, "{ $title }", at its first step (Page Down)
lesson-last = the last step of the last lesson

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = load p = P l/k
axis-largest-angle = largest |φ_i| over a cycle (rad)
axis-damping-level = damping g2 = c2 / √(k m l²)
axis-mass-ratio = mass ratio m1 / (mass beyond joint A)
axis-log-scale = { $axis } (log scale)
axis-first-critical-load = first critical load p
mark-load = load
locus-far-left = { $name }: eigenvalues down to Re λ = { $re } 1/s (fast decaying modes) lie left of the view, which holds those that decide stability
legend-branch-colour = branch colour: the load, p = { $from } to { $to }
legend-eigenvalues-now = eigenvalues at the current load
legend-measured = measured from the run
legend-current-load = current load
legend-overlay-no-change = no change of stability up to the slider's end
legend-overlay = overlay { $name }: { $loads }
legend-transition = p = { $load }: { $from } to { $to }
legend-more-loads = { $count } more critical loads (zieglerlab critical lists them)
legend-no-analysis = no analysis
legend-stronger = stronger: faster growth or decay (strongest: { $largest } 1/s)
legend-critical-loads = critical loads
legend-now = now
legend-now-off = now: off the map ({ $why })
legend-now-no-value = now: not on the map ({ $axis } has no value for this column)
legend-now-below = { $name } = { $value } is below { $bound }
legend-now-above = { $name } = { $value } is above { $bound }
legend-this-model = this model: p = { $load }
legend-straight-stable = straight column, stable
legend-straight-unstable = straight column, unstable
legend-stable-cycle = stable limit cycle
legend-unstable-cycle = unstable limit cycle
legend-hopf-point = flutter onset (Hopf point)
legend-cycle-fold = LPC: fold of cycles
legend-cycle-period-doubling = PD: period doubling
legend-cycle-torus = NS: torus (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC: symmetry breaks (branch point of cycles)
legend-sweep-up = sweep up (a run)
legend-sweep-down = sweep down (a run)
legend-seen-in-ramp = seen during the ramp
legend-largest-angle = this run's largest angle, last period
legend-flutter-soft = flutter onset, soft: a small swing grows
legend-flutter-hard = flutter onset, hard: a jump to a large swing
legend-divergence-onset = divergence onset
legend-special-points = B: Bautin (soft turns hard), BT: Bogdanov-Takens, DH: double Hopf, ZH: zero-Hopf
legend-fold-of-cycles = fold of cycles: below it no swing survives
legend-hysteresis = hysteresis: rest and a large swing both stable
describe-against = { $y } against { $x }
describe-range = { $state } from { $from } to { $to }
describe-ranges = ranges: { $ranges }
describe-mark = { $name } at { $x }
describe-marked = marked: { $marks }
describe-point = { $name } at ({ $x }, { $y })
describe-points = named: { $points }
describe-bands = tinted between a fold of cycles and a hard flutter onset: the band of hysteresis, where rest and a large swing are both stable
describe-curves = { $count ->
    [one] { $count } curve
   *[other] { $count } curves
}
describe-now-stable = at the present load all { $count } eigenvalues lie left of the imaginary axis: a kick dies away
describe-now-flutter = at the present load { $right } of { $count } eigenvalues lie right of the imaginary axis, { $oscillating } of them off the real axis: a swing grows (flutter)
describe-now-divergence = at the present load { $right } of { $count } eigenvalues lie right of the imaginary axis, 0 of them off the real axis: the column bends away (divergence)
describe-map = a map of { $columns } by { $rows } cells: stable { $stable }%, flutter { $flutter }%, divergence { $divergence }%

## The scene, the load bar and the tabs' own words

scene-name = the column
scene-swing = its swing now { $rad } rad
scene-hidden = the column, { $swing }
scene-analysing = the column, { $swing }; its stability is being analysed
scene-stable = stable: a kick dies away, to a hundredth in { $secs } s; { $swing }
scene-undamped = stable but undamped: a kick swings on, neither growing nor dying; { $swing }
scene-flutter = the column flutters: a swing grows, doubling every { $secs } s at { $frequency } rad/s; { $swing }
scene-divergence = divergence: the column bends away from straight, doubling every { $secs } s; { $swing }
scene-stopped = the run stopped: { $status }; R starts a fresh run
scene-drag-hint = drag the tip or a joint to displace the column
scene-whole-reach = whole reach
    .tooltip = frame the whole disc the tip can reach, still; off, the view follows the motion, zooming out at once as the column swings wide and back in as it settles, always with the clamp in view
scene-delta =
    .tooltip = δ: the angle from the last rod's direction (the dashed arrow, where an ideal follower force would point) to the force the band's friction actually applies (the solid arrow), drawn as the arc at the tip. δ = 0 is a perfect follower; the roller turns the force by δ as it slips sideways on the band (eq. 23)
scene-stick-slip = stick-slip: the slip speed is below 1e-4 m/s; Coulomb friction is regularized here, outside the model's validity
scene-band = band moving left at V = { $speed } m/s
load-bar = load{"\u000A"}p = { $load }
    .name = load slider
    .tooltip = the load p = P l/k: click or drag here, or use the arrow keys (with the bar focused: left and right, shift for ten steps, home and end)
load-bar-said = load p = { $load } of 0 to { $end }
load-bar-said-hidden = { $load }: the state is hidden until the lesson reveals it
load-bar-said-analysing = { $load }: analysing
load-bar-said-range = { $load }: { $state }, from p = { $from } to { $to }
load-bar-said-beyond = { $load }: beyond the analysed range
view-hint = drag: pan · Ctrl+scroll: zoom · double-click: fit
    .more = Show all the data again (as a double-click on a plot does).{"\u000A"}Drag or scroll to pan, Ctrl+scroll to zoom, drag a box with the right button to zoom into it.
view-fit = fit
map-readout-growth = growth rate { $rate } 1/s
map-kick-settles = a kick dies out
map-kick-hysteresis = a small kick dies out, a large one leaves it swinging (hysteresis)
map-kick-grows-softly = a kick grows softly to a small swing
map-kick-jumps = a kick jumps to a large swing
map-following = following the flutter boundary and the folds of cycles…
map-not-followed = boundaries not followed: { $why }
map-readout-hint = point at the map to read a cell; click to take its load and parameter
histories-delta = δ: the band force's angle from rod 2
histories-energy = kinetic + spring energy
histories-band-power = power from the band
histories-rod-2 = rod 2
zoom-outside = zoom { $zoom } is outside { $least } to { $most }: set to { $held } (Ctrl+0: 100%)
plot-name = plot: { $y } against { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Computing the root locus of these parameters...
locus-none = No root locus for these parameters.
locus-none-why = No root locus for these parameters: { $why }.
locus-title = root locus, p = { $from } to { $to }
map-rows = rows { $done } of { $total }
map-grey-rows = grey rows have no analysis: { $why }
map-empty-range = map range { $lo } to { $hi } is empty
map-no-thread = no thread for the map: { $why }
map-stopped = the map stopped: { $why }
map-axis = load p against
    .tooltip = the map's second parameter (its range below restarts the map)
map-from = from
    .name = map range from
    .tooltip = where the second parameter starts
map-to = to
    .name = map range to
    .tooltip = where the second parameter ends
paradox-computing = computing the flutter loads as the damping vanishes ...
paradox-joints = The flutter load with joint dampers c1 = (c1/c2) c2 as the damping level g2 = c2 / sqrt(k m l^2) goes to zero: the limit depends on the ratio and lies below the undamped load (Ziegler's paradox).
paradox-external = The flutter load with equal joint dampers c1 = c2 = c (internal damping) and drag c_ext = (c_ext l^3 / c) c / l^3 along the rods (external damping) as the level g2 = c / sqrt(k m l^2) goes to zero: external damping destabilizes too, and the limit depends on the ratio.
paradox-no-extent = the curves have no extent along the ratio
paradox-no-thread = no thread for the curves: { $why }
paradox-dead-load = A dead load (eta = 0) is conservative: it never flutters, so there is no paradox to show.
paradox-stable-throughout = No curve to draw: at every ratio shown the column keeps its stability up to p = { $end }.
paradox-failed = No curve to draw: { $why }.
paradox-kind = damping that vanishes:
paradox-kind-joints = joint dampers
    .tooltip = the joint dampers c1 and c2 in the ratio c1/c2
paradox-kind-external = external drag and internal
    .tooltip = drag c_ext along the rods (external) and equal joint dampers c1 = c2 = c (internal) in the ratio c_ext l^3 / c
paradox-roller = The load at which the roller column first loses stability, against the roller's mass, for three band speeds (the slip damping is mu R / V).
paradox-roller-falling = falling toward zero as nu -> 0
paradox-roller-flat = not falling toward zero over this range
paradox-roller-massless = ; the massless roller (the ideal follower) loses stability at p = { $load }
paradox-roller-caption = { $intro } At the smallest mass shown, nu = { $nu }, the curves stand at { $at }, { $trend }{ $massless }.
record-next = the next
record-secs = s into
    .name = record seconds
    .tooltip = seconds of the window to record (1 to 60)
record-folder =
    .name = record folder
    .tooltip = the folder the GIF goes in
record-choosing = choosing...
record-choose = choose...
    .tooltip = choose the folder in the desktop's dialog
    .title = zieglerlab: the folder for recordings
record-start = record
    .tooltip = record what the window shows, 10 frames a second, to a GIF
    .no-folder = the folder does not exist

## A lesson's revealed results

reveal-never = the column does not lose stability up to p = { $load }
reveal-theory = the theory: unstable from p = { $load }
reveal-seen = ; the motion showed at p = { $load }
reveal-predicted = You predicted p = { $load };{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Right: you chose "{ $chosen }", the answer.
reveal-wrong = Not this one: you chose "{ $chosen }"; the answer is "{ $answer }".
reveal-answer = The answer: "{ $answer }".
reveal-no-answer = the theory has no answer at this load
reveal-period = , a period of { $secs } s
reveal-flutter = flutter: the swing doubles every { $secs } s{ $period }
reveal-divergence = divergence: the lean doubles every { $secs } s
reveal-stable = stable: a kick halves every { $secs } s{ $period }
reveal-undamped = stable: a kick neither grows nor dies away{ $period }
reveal-here = The theory at p = { $load }: { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = rods = { $rods }: the load bar is now 0 to { $end }, and the load moved with it from p = { $from } to { $to } (the same place on the bar; type the load to set another)
notice-rods-load-kept = rods = { $rods }: the load p = { $load } is kept ({ $why })
notice-switched-to-reference = the column is too stiff for the rapier engine at its 1/240 s step (huge damping or stiffness against little mass); switched to the reference engine
notice-lesson-last-step = this was the lesson's last step: close it, or open another from the lessons menu
notice-paste-nothing = nothing to paste: copy settings text first ("copy settings" in the share menu), or type it in the box
notice-paste-not-understood = pasted settings refused, nothing changed: { $what } not understood
notice-pasted = settings pasted
notice-not-saved = not saved: no file chosen (where no dialog opened, this desktop offers none)
recording-saved = recording saved to { $path }: { $frames } frames in { $secs } s{ $slow }
recording-jerky = ; it caught only { $caught } frames a second of the { $fps } a second the GIF is made of (the capture rate: the machine was too busy to take more), so the GIF plays in the right time but jerkily: a smaller window (or projector mode off) records more
recording-title = { $title }: recording, { $secs } s to go
recording-making = making the GIF: frame { $done } of { $kept }
save-as = save as
    .path = save as path
save-as-typed = No file dialog opened on this desktop: type where to save { $what }.
save-as-exists = { $path } exists: replace it? (save again to replace)
save-as-replace = replace
save-as-save = save
save-as-cancel = cancel
save-as-what-table = the table (CSV)
save-as-what-plots = the plots (PNG)
save-as-no-path = type a file's path
save-as-no-folder = its folder does not exist
save-as-folder = it is a folder: type a file's name in it
save-as-pipe = it is a pipe or a device, not a file: type a file's path
save-as-protected = the file exists and may not be written ({ $why }); it is left as it was

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (external / internal)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = damping g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds }: one curve, the first critical load does not depend on V
paradox-reference-undamped = undamped
paradox-reference-massless = nu = 0: the ideal follower
paradox-reference = { $name }: p = { $load }
paradox-reference-above = { $name }: p = { $load } (above the axis)

## Refused values and the engine's failures
## (refused-value: "{ $subject } = { $value }: { $allowed }", with one of the
## allowed-* texts; quantity-* name what is not a parameter's symbol)

refused-value = { $subject } = { $value }: { $allowed }
refused-not-a-number = '{ $text }' is not a number
refused-unknown-preset = unknown preset '{ $name }'; the presets are: { $known }
refused-unknown-key = unknown key '{ $key }'; the keys are: { $known }
refused-malformed = '{ $text }' is not key=value with a number (e.g. load=2.5): { $reason }
refused-conflict = { $first } and { $second } both set the same quantity; give only one
allowed-finite = must be a finite number
allowed-positive = must be > 0
allowed-non-negative = must be >= 0
allowed-key-range = must be a finite number { $range } { $unit }
allowed-key-count = must be a whole number { $range }
allowed-between = must lie between { $min } and { $key } = { $max }
allowed-rods = must be a whole number from 2 to { $most }
allowed-eta-range = must lie between 0 (dead load) and 1 (follower force)
allowed-frictionless-band = must be > 0: without friction the band exerts no load at all (set the load to 0 for an unloaded column)
allowed-friction-too-small = too small: the load p = { $load } would need the normal force R = P / mu beyond every number
allowed-beyond-analysis = beyond what the analysis can square (sizes { $smallest } to { $largest })
allowed-makes-beyond-analysis = makes { $what } beyond what the analysis can square (sizes { $smallest } to { $largest })
allowed-masses-too-unequal = the masses are too unequal: the determinant of the mass matrix is below 1e-12 of its scale, so rounding decides the motion (e.g. a tip mass or roller over about 1e12 times the rods')
allowed-mass-missing = the column needs mass beyond the joint A (rod 2, tip or roller) and mass or inertia that moves with rod 1 on its own; the mass matrix is singular
allowed-chain-massless = a chain needs mass or inertia on every copy of rod 2 (m2 or I2 > 0): with rod 2 massless the chain's mass matrix is singular
allowed-needs-damped-joint2 = needs a damped joint 2: set c2 > 0 (or the damping level) first
allowed-infinite-damper-ratio = c2 = 0 with c1 > 0: the ratio c1/c2 to hold is infinite; set c2 > 0 first
allowed-band-at-rest = must be > 0 for the linear analysis: at V = 0 Coulomb friction is not differentiable about rest (stick-slip)
allowed-roller-has-no-eta = the roller has no eta: the band's friction sets the force's direction, against the contact's slip, and its angle delta from rod 2 is an outcome of the motion, not a parameter
allowed-state-length = must be 2 (rods + 1): the angles, the spin and their rates
allowed-time-step = must be a time step in (0, 1] s
quantity-load-force = the load P
quantity-load-p = the load p = P l/k
quantity-inertia-o = the inertia about O
quantity-inertia-coupling = the coupling inertia
quantity-inertia-a = the inertia about A
quantity-stiffness-k1 = the stiffness k1
quantity-stiffness-k2 = the stiffness k2
quantity-damper-c1 = the damper c1
quantity-damper-c2 = the damper c2
quantity-drag = the drag c_ext l^3
quantity-slip-damping = the slip damping mu R l^2 / V
quantity-spin-inertia = the roller's spin inertia m3 r^2 / 2
quantity-mass-matrix = mass matrix
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = the state's length
quantity-time-step = dt
engine-too-stiff = the rapier engine cannot integrate this column at dt = { $step } s: its springs and dampers reach rates of { $rate } 1/s, which need dt < { $need } s; use the reference engine
engine-rapier-world = the rapier2d world could not be built for this column (its joints were refused); use the reference engine
analysis-not-converged = the eigenvalue iteration did not converge at load p = { $load }
ramp-refused-end = { $end } = { $value }: must be a load p >= 0
ramp-refused-rate = ramp rate = { $value }: must be a positive load per second
ramp-refused-too-slow = ramp rate = { $value }: must be at least { $slowest } load per second (slower, the load would not move visibly within days)
ramp-refused-too-long = ramp from { $from } to { $to } at { $rate } per second takes { $secs } s of simulated time; at most { $most } s (about four months): a faster rate or nearer ends
ramp-refused-model = { $end } = { $value }: { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = ramp: { $why }
notice-ramp-stopped = ramp stopped: { $why }
notice-map-point-refused = map: { $why }
notice-overlay-unavailable = overlay unavailable: { $why }
notice-table-not-saved = not saved: { $why }
notice-no-locus = there is no root locus for these parameters
notice-no-thread = not saved: no thread to write with ({ $why })
notice-saved-lines = saved { $count ->
    [one] { $count } line
   *[other] { $count } lines
} to { $path }
notice-write-failed = not saved: { $why }
notice-plots-saved = saved the plots to { $path }
notice-plots-not-saved = the plots not saved: { $why }
notice-recording-failed = recording failed: { $why }
notice-layout-not-saved = window layout not saved: { $why }
notice-stored-overlay = the stored overlay { $name } is not a preset; no overlay
notice-stored-map-axis = the stored map axis is not used: { $why }
notice-stored-language = the stored language is not used: { $why }
notice-lesson-refused = lesson { $name }: { $why }
notice-lesson-not-opened = lesson not opened: { $why }
notice-reset-closed-lesson = reset all: the lesson "{ $title }" is closed (open it again from the lessons menu)

## The post-critical tab's notes: each onset and where its branch of
## cycles ended

cycles-computing = following the limit cycles from each flutter onset ...
cycles-none = no limit cycles: { $why }
cycles-no-onset = no flutter onset in the load bar's range: no limit cycles
cycles-chain-too-long = a chain of { $rods } rods takes too long to follow in the window (16 rods take about 20 s on two cores, and the work grows faster than the number of rods); `zieglerlab bifurcation` computes its cycles from the command line
cycles-no-thread = no thread for the cycles: { $why }
cycles-branch = { $name }: { $onset } onset at p = { $at }; the branch ended: { $end }
cycles-offshoot = { $name }: asymmetric cycles (and their mirror images) from the BPC at p = { $at }; the branch ended: { $end }
cycles-onset-soft = soft
cycles-onset-hard = hard
cycles-no-branch = flutter onset at p = { $at }: { $why }
cycles-no-branch-reversible = no damping, a reversible column: no limit cycle to follow
cycles-no-branch-degenerate = the first Lyapunov coefficient is zero within its accuracy; cycles not followed
cycles-no-branch-not-converged = the shooting did not converge next to the onset; no cycles
cycles-end-left-range = left the load range
cycles-end-large-amplitude = an angle's amplitude passed { $most } rad (the column swings round)
cycles-end-long-period = the period grew past { $most } times the onset's
cycles-end-lost = the shooting did not converge past p = { $load }
cycles-end-stick-slip = the roller's contact nears sticking on the band past p = { $load } (stick-slip: the friction is not smooth there)
cycles-end-unresolved = the cycles past p = { $load } are not resolved (trivial multiplier off 1 by more than { $tolerance })
cycles-end-point-limit = { $most } cycles computed
cycles-end-cancelled = stopped on request

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = the stability is not resolved: at p = { $load } the modes span { $fastest } 1/s to { $slowest } 1/s, a ratio beyond { $span }, so the slow modes' growth rates are left to rounding (a mode far faster than the others, such as the spin of a roller of tiny mass nu)
not-resolved-slow-mode-lost = the stability is not resolved: at p = { $load } the modes span { $scale } 1/s to { $slowest } 1/s, so growth rates below { $tolerance } 1/s are lost to rounding (the model is near a singular limit: a very slow band V, or very large damping)
not-resolved-methods-disagree = the stability is not resolved: at p = { $load } the tracked roots and the Schur decomposition disagree on the state (rounding decides it: a mode far faster than the others, such as the spin of a roller of tiny mass nu); the critical loads shown may be spurious or missing
not-resolved-rounding-decides = the stability is not resolved: for p from { $low } to { $high } the growth rates lie between 1e-12 and 1e-10 of the frequency scale, where rounding decides the state (a roller of tiny mass nu, whose weak flutter grows in proportion to nu, or a very slow band V); the critical loads shown may be misplaced or missing
not-resolved-refinement-cut = the root locus was refined only up to p = { $load }: beyond it the branches are sampled at the evenly spaced loads alone, so a window of another state narrower than their spacing may be missing (the refinement's bound on time and memory was reached)

## The stored state's check before the window opens (a damaged store)

store-zoom = the zoom factor { $zoom } (allowed 0.2 to 5)
store-geometry = the window geometry { $width } x { $height } points at scale { $scale }
store-unreadable = the stored state could not be read ({ $why }); a copy is kept at { $copy }; starting from the defaults
store-unreadable-uncopied = could not be read ({ $why }) nor copied ({ $error })
store-moved = the stored state { $path } { $why }; it is moved to { $aside } and the defaults are used
store-not-moved = the stored state { $path } { $why } and could not be moved aside ({ $error }); settings will not be saved
store-folder-not-made = settings will not be saved: the folder { $folder } cannot be made ({ $error })
store-folder-full = settings will not be saved: the folder { $folder } takes no new file ({ $error })
store-not-writable = settings will not be saved: { $path } cannot be written ({ $error })
store-is-folder = is a folder
store-is-device = is a device, a pipe or a socket
store-too-large = holds { $bytes } bytes (at most { $most } are read)
store-entry = { $why } (eframe's '{ $key }' entry)
store-ignored = stored state: ignored { $what }
store-ignored-not-rewritten = stored state: ignored { $what } (the file could not be rewritten: { $error })
store-settings-unreadable = the stored settings could not be read
store-original-kept = the original is kept at { $copy }
store-original-lost = no copy of the original could be kept ({ $error })
store-settings-partly = stored settings: ignored { $what }; kept the rest
store-settings-ignored = stored settings ignored ({ $why }); starting from the defaults
layout-ignored = stored window layout ignored ({ $why }); the default layout is used
notice-paste-unreadable = pasted settings not understood, nothing changed: { $why }
notice-paste-refused = pasted settings refused, nothing changed: { $why }
notice-analysis-unavailable = analysis unavailable: { $why }
notice-lesson-step = lesson step { $step }: { $why }
notice-lesson = lesson: { $why }
