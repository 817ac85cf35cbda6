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
