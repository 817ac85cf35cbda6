### zieglerlab: die Texte des Fensters auf Deutsch.
###
### Dieselben Nachrichten wie en.ftl, mit denselben Platzhaltern; Zahlen
### kommen fertig geschrieben an, mit Dezimalpunkt wie in der Kommandozeile.
###
### Glossar (überall gleich verwendet):
###   flutter: Flattern (flattern)          divergence: Divergenz
###   follower force: Folgelast              dead load: Totlast
###   critical load: kritische Last          root locus: Wurzelortskurve
###   eigenvalue: Eigenwert                  growth rate: Anwachsrate
###   damping: Dämpfung                      limit cycle: Grenzzyklus
###   Hopf bifurcation: Hopf-Verzweigung (weicher / harter Einsatz)
###   rod: Stab     column: Säule            spring: Drehfeder
###   roller: Rolle  moving band: laufendes Band   friction: Reibung
###   stability map: Stabilitätskarte        Ziegler's paradox: Ziegler-Paradoxon

## Counts

rods-count = { $count ->
    [one] { $count } Stab
   *[other] { $count } Stäbe
}

## The sidebar's heading and its menus

menu-share = teilen
    .tooltip = die Einstellungen als Text: kopieren oder einfügen
menu-record = aufnehmen
    .tooltip = das Fenster als GIF aufnehmen
menu-keys = Tasten
    .tooltip = die Befehle der Tastatur
menu-language = die Sprache des Fensters (für den nächsten Start gemerkt)
    .name = Sprache: { $language }
projector-toggle = Beamer (P)
overlay = Vergleich
    .none = keiner
    .tooltip = die Wurzelortskurve eines anderen Modells in Grau, beim selben a (wie Abb. 8 die ideale Säule neben die Rolle stellt)
section-parameters = Parameter

## The status line at the window's foot

status-dismiss = schließen
    .tooltip = diese Meldung entfernen
status-latest = die letzte Meldung (der ganze Text)
status-got-it = verstanden
    .tooltip = den Hinweis ausblenden
status-ready = bereit
hint-first-launch = Den Lastregler auf etwa 3 ziehen und K drücken, um die Säule anzustoßen (Leertaste hält an).

## The tabs

tab-locus = Wurzelortskurve
    .tooltip = die Wurzelortskurve: die Eigenwerte der Säule in der komplexen Ebene und über der Last. Links der senkrechten Achse klingt eine Bewegung ab, rechts wächst sie; die Höhe ist die Frequenz. Das Flattern beginnt, wo ein Paar die Achse kreuzt
tab-histories = Zeitverläufe
    .tooltip = die Winkel, die Energie und die Leistung des Bandes während des Laufs
tab-map = Stabilitätskarte
    .tooltip = die Stabilität jeder Last über einem zweiten Parameter
tab-paradox = Paradoxon
    .tooltip = die erste kritische Last, wenn die Dämpfung (oder die Masse der Rolle) verschwindet
tab-post-critical = überkritisch
    .tooltip = jenseits des Flatterbeginns: die Größe der Grenzzyklen über der Last, stabil oder nicht, und der eigene Ausschlag der laufenden Säule
save-png = PNG speichern...
    .tooltip = diese Diagramme als Bild, ohne Schaltflächen und Hinweise
save-csv = CSV speichern...
    .tooltip = die Zahlen hinter diesen Diagrammen, in den Spalten der Kommandozeile, in eine Datei
answer-hidden = Dieses Diagramm zeigt die Antwort: Es kehrt zurück, wenn die Lektion sie auflöst.
answer-hidden-histories = { answer-hidden } Die Zeitverläufe zeigen, was die Säule tut.
tab-in-column-place = Der Reiter „{ $tab }“ steht an der Stelle der Säule; der Reiter Wurzelortskurve bringt die Säule zurück.
locus-beside-column = Die Wurzelortskurve steht neben der Säule; ein hier gewählter Reiter erscheint an der Stelle der Säule.
plots-need-room = Die Diagramme brauchen hier mehr Platz: ein höheres Fenster oder den Beamermodus aus (P).

## The welcome of a first launch

welcome-title = Willkommen bei zieglerlab
welcome-column = Zwei Stäbe auf Drehfedern stehen, an einem Ende eingespannt. Am anderen Ende drückt eine Kraft längs des letzten Stabes und dreht sich mit ihm: eine Folgelast. Hier entsteht sie wie im Labor durch eine Rolle, die ein laufendes Band mitzieht.
welcome-states = Bei kleinen Lasten schwingt die Säule nach einem Stoß und bleibt klein: Sie ist stabil. Oberhalb einer kritischen Last flattert sie: Sie schwingt hin und her, immer weiter. Bei noch größeren Lasten kann sie divergieren: Sie biegt ohne zu schwingen zur Seite aus.
welcome-locus = Die Wurzelortskurve zeigt als Zahlen (die Eigenwerte), wie sich die Säule bewegt, während die Last wächst. Links der senkrechten Achse klingt ein Schwingen ab, rechts davon wächst es. Wie weit rechts, ist die Anwachsrate; wie hoch, die Frequenz.
welcome-try = Den Lastregler ziehen und beides beobachten: Die Säule beginnt bei der Last zu flattern, bei der die Eigenwerte die Achse kreuzen.
welcome-first-lesson = die erste Lektion beginnen
    .tooltip = ein paar Schritte: vorhersagen, wo das Flattern beginnt, dann zusehen
welcome-explore = selbst erkunden
    .tooltip = dies schließen; die Lektionen bleiben oben in der Seitenleiste

## States and critical loads

state-stable = stabil
state-flutter = Flattern
state-divergence = Divergenz
transition = p = { $load }: { $from } -> { $to }
transition-meaning = p = { $load }: Die Säule geht von { $from } zu { $to } über; { $how }
    .to-flutter = oberhalb dieser Last liegt ein Eigenwertpaar rechts der imaginären Achse: Ein Stoß wächst zu einem immer größeren Schwingen an
    .to-divergence = oberhalb dieser Last ist ein reeller Eigenwert positiv: Die Säule neigt sich weg, ohne zu schwingen
    .to-stable = oberhalb dieser Last liegt kein Eigenwert rechts der imaginären Achse: Ein Stoß wächst nicht mehr an
duration-forever = nie
duration-days = { $count ->
    [one] { $n } Tag
   *[other] { $n } Tage
}
duration-years = { $count ->
    [one] { $n } Jahr
   *[other] { $n } Jahre
}

## The model and the engine

model = Modell
    .source = { $source }: wo das Modell in der Studie steht, der dieses Programm folgt (ihre Abbildung und Gleichungen)
preset-ziegler-1952 = Ziegler 1952
    .description = Zieglers Säule: masselose Stäbe, Punktmasse 2m im Gelenk A und m an der Spitze, ideale Folgelast
preset-uniform-rods = Abb. 1a
    .description = Homogene starre Stäbe der Masse m (Abb. 1a), ideale Folgelast
preset-midpoint-masses = Abb. 1b, Gl. 1-7
    .description = Masselose Stäbe mit einer Punktmasse m in jeder Stabmitte (Abb. 1b, Gl. 1-7), ideale Folgelast
preset-roller = Abb. 7, Gl. 8-38
    .description = Homogene Stäbe mit einer Rolle, die ein laufendes Band mitzieht (Abb. 7, Gl. 8-38), konsistente Drehträgheit; Parameter aus Abb. 8
preset-roller-as-printed = Gl. 39, Abb. 8
    .description = Das Rollenmodell wie in Gl. (39) gedruckt: die Drehträgheit mit r/l2 multipliziert, ein Druckfehler der Arbeit; Parameter aus Abb. 8
preset-tabletop = Vorlesungstempo
    .description = Eine Säule in Tischgröße für die Vorlesung: homogene Stäbe von 25 cm und 100 g, Federn von 0.0625 N m/rad (a = 10 1/s^2), ideale Folgelast; ab p = 2.54 flattert sie mit einer Periode von etwa 1.5 s
preset-tabletop-roller = Vorlesungstempo
    .description = Die Tischsäule, geschoben von einer 10-g-Rolle mit 2.5 cm Radius auf einem Band mit 0.1 m/s (nu = rho = mu = 0.1): ein schwaches Flattern ab p = 0.024, das Minuten zum Anwachsen braucht, ein starkes nahe der Last der idealen Säule
preset-beck = Beck 1952, eine Kette aus 16 Stäben
    .description = Becks Säule als Kette aus 16 homogenen Stäben mit Federn k in jedem Gelenk (ein Balken mit EI = k l, L = 16 l), Folgelast: Flattern bei P L^2/EI = 18.78 (Becks kontinuierliche Säule: 20.05)
preset-pflueger = Pflügers Säule, eine Kette aus 16 Stäben
    .description = Pflügers Säule: Becks Kette aus 16 Stäben mit einer Spitzenmasse von der halben Masse der Säule, Folgelast: die Spitzenmasse senkt die Flatterlast auf P L^2/EI = 15.06
preset-beck-roller = Becks Kette, belastet wie bei Bigoni et al. 2018
    .description = Becks Kette aus 16 Stäben, belastet durch die Rolle auf dem laufenden Band (die Kennzahlen der Arbeit an jedem Stab: Rollenmasse 0.1 m, Radius 0.1 l, mu = 0.1, V = 0.1 m/s): die Dämpfung durch das Gleiten lässt sie ab P L^2/EI = 0.025 schwach flattern (Anwachsrate unter 3e-4 1/s) und stark ab etwa 18.8, wo die Kette unter Folgelast flattert
preset-pflueger-roller = Pflügers Kette, belastet wie bei Bigoni et al. 2018
    .description = Pflügers Kette aus 16 Stäben (Spitzenmasse die halbe Stabmasse), belastet durch dieselbe Rolle auf dem laufenden Band: schwaches Flattern ab P L^2/EI = 0.008 (Anwachsrate unter 4e-5 1/s), starkes Flattern ab 15.06, wo die Kette unter Folgelast flattert
tip-force-dead = Kraft an der Spitze: eine Totlast (eta = 0), richtungstreu, anstelle der Folgelast des Modells
tip-force-partial = Kraft an der Spitze: teilweise tangential, um eta = { $eta } des Winkels des letzten Stabes gedreht (die Folgelast des Modells hat eta = 1)
engine = Integrator
    .tooltip = was die Bewegung integriert: Der Lauf geht dort weiter, wo er ist
engine-rapier = rapier
    .tooltip = rapier: die Physik-Engine rapier2d, Stäbe als starre Körper mit Gelenken (ein Mehrkörpersystem), der Spin der Rolle implizit
engine-reference = Referenz
    .tooltip = adaptives Dormand-Prince 5(4) auf den exakten Gleichungen

## The load

load-field = Last p = P l/k
    .tooltip = eine Last eingeben (Enter übernimmt, Escape stellt wieder her); auch über das Ende des Reglers hinaus
    .meaning = die Last ohne Einheit: die Kraft P an der Spitze mal die Stablänge l durch die Federsteifigkeit k (Zieglers Säule flattert ab p = 2.09)
roller-load = Rolle: q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = die eigene Last der Rolle: die Kraft R, die sie auf das Band drückt, in den Einheiten von p; die Reibung des Bandes schiebt mit μ R, also p = μ q
notes-more = ... und { $count } weitere (darauf zeigen)
load-beyond-range = p = { $load } liegt außerhalb des gezeichneten Bereichs (0 bis { $end }); der Status unten gilt bei p
critical-loads-hidden = Die kritischen Lasten sind verborgen, bis die Lektion sie auflöst.
not-resolved = die Stabilität ist hier nicht aufgelöst (darauf zeigen für den Grund)
ramp-visible = die Spitze um { $percent } % der Länge ausgelenkt
ramp-theory = Theorie (weiße Marke): instabil ab p = { $load }
ramp-seen = gesehen (Marke): Bewegung sichtbar bei p = { $load } ({ $visible })
ramp-seen-late = gesehen (Marke): Bewegung sichtbar bei p = { $load }, verspätet: darauf zeigen für den Grund ({ $visible })
    .why = Sie zeigt sich verspätet: Nach dem Einsatz braucht die Bewegung Zeit, um sichtbar groß zu werden, und die Rampe läuft inzwischen weiter. Eine langsamere Rampe zeigt sie näher an der Theorie.
ramp-watching = warten, bis die Bewegung sichtbar wird ({ $visible })

## The parameters

groups = dimensionslose Kennzahlen
    .tooltip = die wenigen Kombinationen der SI-Werte, die die Bewegung bestimmen (a = k/(m l^2) legt fest, wie schnell sie ist; nu, rho, mu und V der Rolle ihre Masse, Größe, Reibung und die Geschwindigkeit des Bandes); eine zu ändern lässt die anderen gleich
si-parameters = SI-Parameter
mu-moves-load = (R fest: verschiebt p)
key-allowed = { $description } (erlaubt: { $range })
refused = abgelehnt: { $why }
key-load = Last p = P l/k auf der gemeinsamen Achse (P = mu R für die Rolle; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2): setzt k1 (und k2 im selben Verhältnis), hält p
    .range = > 0
key-nu = nu = m3/m, Masse der Rolle durch die Masse des Stabes
    .range = >= 0
key-rho = rho = r/l, Radius der Rolle durch die Länge des Stabes
    .range = in (0, l2/l]
key-mu = Reibungskoeffizient; nur mu R geht in die Gleichungen ein, also bleibt R fest und die Last p = mu R l/k ändert sich
    .range = > 0
key-V = Geschwindigkeit des Bandes (es läuft in Richtung -x); die lineare Analyse braucht V > 0
    .range = >= 0
key-l1 = Länge von Stab 1 (seine Massenverteilung skaliert mit)
    .range = > 0
key-l2 = Länge von Stab 2 (seine Massenverteilung skaliert mit)
    .range = > 0
key-m1 = Masse von Stab 1, Punktmassen darauf eingeschlossen (Verteilung bleibt)
    .range = >= 0
key-m2 = Masse von Stab 2 (Verteilung bleibt)
    .range = >= 0
key-s1 = Schwerpunkt von Stab 1, ab der Einspannung O
    .range = in [0, l1]
key-s2 = Schwerpunkt von Stab 2, ab dem Gelenk A
    .range = in [0, l2]
key-I1 = Trägheitsmoment von Stab 1 um seinen Schwerpunkt
    .range = >= 0
key-I2 = Trägheitsmoment von Stab 2 um seinen Schwerpunkt
    .range = >= 0
key-m_tip = Punktmasse an der Spitze B (die Masse der Rolle ist m3)
    .range = >= 0
key-k1 = Drehfeder an der Einspannung O
    .range = > 0
key-k2 = Drehfeder im Gelenk A
    .range = > 0
key-c1 = viskoser Dämpfer an der Einspannung O
    .range = >= 0
key-c2 = viskoser Dämpfer im Gelenk A
    .range = >= 0
key-c_ext = äußerer viskoser Widerstand längs beider Stäbe (Luftwiderstand, linearisiert): eine Kraft je Längeneinheit von c_ext mal der örtlichen Quergeschwindigkeit des Stabes
    .range = >= 0
key-rods = Stäbe der Kette: Stab 1, dann Kopien von Stab 2 mit Feder und Dämpfer von Gelenk A in jedem Gelenk; Spitzenmasse und Last am Ende des letzten Stabes
    .range = von 2 bis 64
key-P = Betrag der Kraft an der Spitze
    .range = >= 0
key-eta = Tangentialität der Kraft an der Spitze: Ihre Richtung dreht sich um eta mal den Winkel des letzten Stabes (1: Folgelast, 0: Totlast)
    .range = in [0, 1]
key-m3 = Masse der Rolle (0: masselos, die ideale Folgelast)
    .range = >= 0
key-r = Radius der Rolle
    .range = in (0, l2]
key-R = Normalkraft der Rolle auf das Band
    .range = >= 0

## Time

command-play = Start
    .running = Pause
    .tooltip = Start / Pause
command-load-up = Last höher
    .tooltip = die Last um ein Hundertstel des Lastreglers erhöhen
command-load-down = Last tiefer
    .tooltip = die Last um ein Hundertstel des Lastreglers senken
command-kick = Stoß
    .tooltip = Stoß: jeder Stab um 0.03 rad gedreht
command-reset = Neustart
    .tooltip = Neustart: ein neuer Lauf aus der Standardstörung
command-reset-all = alles zurück
    .tooltip = alles zurücksetzen: die Parameter und die Last des Modells, normale Geschwindigkeit, ein neuer Lauf, die Standardansichten; eine offene Lektion wird geschlossen
command-projector = Beamermodus
    .tooltip = Beamermodus: hoher Kontrast, große Schrift
command-next = weiter
    .tooltip = der nächste Schritt der Lektion (die Fernbedienung eines Vortragenden sendet Bild ab)
command-back = zurück
    .tooltip = der vorige Schritt der Lektion (Bild auf)
command-full-screen = Vollbild
    .tooltip = Vollbild: das Fenster füllt den Bildschirm (nochmals zum Verlassen)
command-step = Schritt
    .tooltip = ein Schritt des Integrators (1/240 s), dann Pause
key-space = Leertaste
key-right = rechts
key-up = oben
key-left = links
key-down = unten
key-page-down = Bild ab
key-page-up = Bild auf
focus-keys-tab = das nächste Bedienelement (Umschalt+Tab: das vorige)
    .keys = Tab
focus-keys-ctrl-tab = der nächste Reiter (Strg+Umschalt+Tab: der vorige)
    .keys = Strg+Tab
focus-keys-press = mit einer Schaltfläche, einem Kästchen, einer Auswahl oder einem Reiter im Fokus: betätigen (die Leertaste startet nur ohne Fokus)
    .keys = Leertaste, Enter
focus-keys-slider = mit einem Regler im Fokus (Lastregler, Vorhersage): um ein Hundertstel verschieben; Umschalt: ein Zehntel
    .keys = links, rechts
focus-keys-column = mit der Säule im Fokus (Tab bis zu ihr): um 0.02 rad in jede Richtung drehen, Umschalt: 0.1 rad (das Ziehen per Tastatur)
    .keys = links, rechts
focus-keys-ends = mit dem Lastregler oder der Vorhersage im Fokus: ihre Enden
    .keys = Pos1, Ende
focus-keys-plot = mit einem Diagramm im Fokus (Tab bis zu ihm): um ein Zehntel verschieben, um die Mitte zoomen; Enter: eine Karte übernimmt die Zelle unter dem Kreuz
    .keys = Pfeile, +, -
focus-keys-escape = den Fokus loslassen (ein Textfeld: die Eingabe rückgängig machen)
    .keys = Esc
focus-keys-others = Bild ab, Bild auf, K, R, P und oben/unten wirken bei jedem Fokus, außer in einem Textfeld in Bearbeitung
    .keys = die übrigen
pace-slow = Langsam
    .tooltip = ein Viertel der Echtzeit
pace-normal = Normal
    .tooltip = Echtzeit: eine simulierte Sekunde pro Sekunde
pace-fast = Schnell
    .tooltip = viermal die Echtzeit
speed-factor = × Tempo
    .tooltip = simulierte Sekunden pro Sekunde Uhrzeit
run-time = t = { $secs } s   ({ $status })
run-paused = angehalten
run-running = läuft
run-diverged = divergiert bei t = { $secs } s
run-too-stiff = zu steif für den Referenzintegrator bei t = { $secs } s: eine sehr leichte Rolle oder ein stehendes Band (der Integrator rapier kommt damit zurecht), oder eine Last oder Steifigkeit so groß, dass kein Schritt die Raten der Säule auflöst
run-too-fast = zu schnell für den Integrator rapier bei t = { $secs } s: Die Säule dreht sich mit { $rate } rad/s, mehr als sein fester Schritt auflöst ({ $most } rad pro Schritt); der Referenzintegrator folgt ihr
run-lagging = läuft mit { $achieved }x: dieser Rechner schafft { $asked }x nicht

## The status card

card-stable =
    .meaning = stabil: ein kleiner Stoß bleibt klein (er klingt ab oder behält ganz ohne Dämpfung seine Größe)
card-flutter =
    .meaning = Flattern: Die Säule schwingt hin und her, immer weiter (ein Eigenwertpaar rechts der Achse)
card-divergence =
    .meaning = Divergenz: Die Säule biegt ohne zu schwingen zur Seite aus (ein reeller Eigenwert rechts der Achse)
card-weak-flutter = schwaches Flattern
    .meaning = schwaches Flattern: Das Schwingen wächst, aber um weniger als 1 % seiner Frequenz: langsam, über viele Schwingungen
card-hidden = stabil oder nicht?
    .why = Das Urteil ist verborgen, bis die Lektion es auflöst: die Säule beobachten.
card-no-figures = keine Stabilitätswerte: { $why }
card-growth = Anwachsrate  { $rate } 1/s
    .tooltip = Anwachsrate: wie schnell die Bewegung wächst (positiv) oder abklingt (negativ), pro Sekunde: der Realteil des am weitesten rechts liegenden Eigenwerts
card-growth-zero = Anwachsrate  0 (bis auf { $tolerance } 1/s)
card-not-resolved = bei diesen Parametern nicht aufgelöst: siehe die Warnung unter der Last
card-e-folding = Anwachszeit  { $time }
    .tooltip = Anwachszeit: die Zeit, in der das Schwingen um den Faktor e = 2.72 wächst (1 / Anwachsrate)
card-decay = Abklingzeit  { $time }
    .tooltip = Abklingzeit: die Zeit, in der das Schwingen um den Faktor e = 2.72 abnimmt
card-neutral = neutral: kein Wachsen, kein Abklingen
card-mode = Mode { $k } von { $n }
card-the-mode = die Mode
card-frequency = Frequenz  { $frequency } rad/s  (Periode { $period } s{ $which })
    .tooltip = Frequenz: wie schnell die Säule schwingt, in Radiant pro Sekunde (die Höhe des Eigenwerts); die Periode ist eine volle Schwingung. Eine Säule aus n Stäben hat n Schwingungsmoden, hier von der langsamsten an gezählt; die Karte beschreibt die am schnellsten wachsende (oder am langsamsten abklingende), und die Messung aus dem Lauf gilt derselben Mode
card-non-oscillatory = nicht schwingend: der dominante Eigenwert ist reell
card-measured = gemessen aus dem Lauf{ $mode }  { $measurement }
    .tooltip = der an die eigene Bewegung des Laufs angepasste Eigenwert (ein Matrixbüschel der Winkel): mindestens 20 s kleiner Schwingungen (unter 0.05 rad) seit dem letzten Stoß, Loslassen oder Ändern, jede Mode, sobald der Lauf eine ganze Periode von ihr enthält; „Mode 2 von 2“ zählt die Schwingungsmoden der Säule von der langsamsten an. Das ± ist die eigene Unsicherheit der Anpassung: wie weit Anpassungen über das erste und das letzte Dreiviertel des Laufs von der über den ganzen Lauf abweichen. Auch der Zeitschritt dt des Integrators entfernt den Lauf selbst vom linearen Modell, seine Frequenz um etwa ω³dt²/24
card-measured-other-mode = gemessen aus dem Lauf: nur { $mode }, { $measurement } ({ $card } der Karte in diesem Lauf zu schwach für eine Anpassung)
card-measured-other = gemessen aus dem Lauf: nur ein anderer Eigenwert, { $measurement } (der der Karte in diesem Lauf zu schwach für eine Anpassung)
card-measured-after = gemessen: nach 20 s Bewegung mit kleiner Amplitude (|φ| < 0.05 rad)
card-measured-two-rods = gemessen: nur bei zwei Stäben (die vielen langsamen Moden einer Kette bräuchten einen längeren Lauf, als eine Anpassung nutzen kann)
card-measurement = Anwachsen { $growth } 1/s, Frequenz { $frequency } rad/s
card-measurement-unknown = Anwachsen { $growth } 1/s, Frequenz { $frequency } rad/s (Unsicherheit unbekannt: zu wenige Perioden im Lauf)
card-grows-slowly = wächst um { $percent } pro Periode: minutenlang beobachten, nicht sekundenlang
card-grows-too-slowly = wächst um { $percent } pro Periode: zu langsam, um es in einer Lektion zu sehen
onset-soft = weicher Einsatz bei p = { $at }: Das Schwingen geht in einen Grenzzyklus über, der von null an wächst
onset-soft-roller = weicher Einsatz bei p = { $at }: ein Zyklus wächst von null an, bis die Rolle fast haftet
onset-hard = harter Einsatz bei p = { $at }: Das Schwingen springt auf einen großen Zyklus, der auch unterhalb des Einsatzes bleibt
onset-degenerate = Einsatz bei p = { $at }, in erster Ordnung weder weich noch hart
onset-reversible = keine Dämpfung: kein Grenzzyklus, auf dem sich das Schwingen einpendeln könnte (eine reversible Säule)
    .tooltip = Ohne Dämpfung ist die Säule reversibel: Das Flattern beginnt, wo sich zwei Eigenwertpaare auf der imaginären Achse treffen, und es gibt keinen Attraktor, also keinen Grenzzyklus, auf dem sich das Schwingen einpendeln könnte.
onset =
    .tooltip = Weich: Nach dem Einsatz wächst das Schwingen von null zu einem kleinen stationären Zyklus, größer mit steigender Last; hart: Es springt auf einen großen, der bleibt, wenn die Last etwas gesenkt wird. Haften: Die Rolle hört auf, auf dem Band zu gleiten, wo die Reibung ihr Gesetz ändert.{"\u000A"}{"\u000A"}Erster Ljapunow-Koeffizient { $lyapunov } beim Einsatz p = { $at } (Hopf-Punkt, Frequenz { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = In seiner Nähe ist |phi1| des Zyklus etwa { $a } sqrt(p - { $at }) rad.
onset-sticking = Auf der Rolle nimmt der Schlupf am Kontakt ab, während der Zyklus wächst; wo er fast null wird, ist die Reibung nicht mehr glatt, und die Bewegung geht in Haftgleiten über, dem diese Analyse nicht folgt: Der Zweig im Reiter überkritisch endet dort.

## The load ramp

ramp = Lastrampe
ramp-from = von
    .name = Rampe von
    .tooltip = die Last, bei der die Rampe beginnt
ramp-to = bis
    .name = Rampe bis
    .tooltip = die Last, bei der die Rampe endet
ramp-rate = mit
    .name = Rampenrate
    .tooltip = wie schnell sich die Last ändert, pro simulierter Sekunde
ramp-start = Rampe starten
    .tooltip = die Last geht auf „von“ und läuft mit der Rate nach „bis“, während der Lauf weitergeht (die Last von Hand setzen beendet sie)
ramp-pause = Rampe anhalten
    .tooltip = die Last halten, wo sie ist; der Lauf geht weiter
ramp-resume = fortsetzen
ramp-stop = beenden
    .tooltip = die Rampe beenden
ramp-done = fertig
ramp-paused = angehalten
ramp-moving = läuft
ramp-progress = p = { $load } Richtung { $to } mit { $rate }/s ({ $doing })

## Sharing the settings

share-copy = Einstellungen kopieren
    .tooltip = Modell, Last, Integrator und Tempo als Text, in die Zwischenablage und das Feld darunter
share-paste = aus der Zwischenablage einfügen
    .tooltip = anderswo kopierten Einstellungstext übernehmen (das Feld darunter zeigt ihn)
share-box = oder Einstellungstext hier tippen oder einfügen
share-take = den Text oben übernehmen
    .tooltip = die im Feld geschriebenen Einstellungen laden
paste-too-long = Einfügen abgelehnt, nichts geändert: der Text hat { $bytes } Bytes; kein Feld hier nimmt mehr als { $most } (Einstellungstext hat unter 2000)
paste-no-text = Einstellungen einfügen: Die Zwischenablage enthält keinen Text (zuerst den Einstellungstext kopieren)

## Lessons

lessons = Lektionen
lessons-built-in = die eingebaute Lektion { $name }
lesson-file = Lektionsdatei
    .hint = eine Lektionsdatei (.ron)
    .tooltip = der Pfad zu einer eigenen Lektionsdatei (das Format steht in der README)
lesson-open = öffnen
    .tooltip = die Datei lesen und prüfen, dann starten
lesson-reading = lese { $path }
lesson-reading-stopped = { $path }: Das Lesen endete ohne Antwort
lesson-step = Schritt { $k } von { $n }
lesson-prediction = deine Vorhersage: p = { $load }
lesson-predicted-load = vorhergesagte Last
    .tooltip = wo du ihn erwartest; der Lastregler markiert ihn (Tasten wie beim Lastregler: links, rechts, Umschalt für zehn Schritte, Pos1, Ende)
lesson-back = zurück
    .tooltip = der vorige Schritt (Bild auf)
lesson-next = weiter
    .tooltip = der nächste Schritt: Er stellt ein und startet, was er sagt (Bild ab, wie es die Fernbedienung eines Vortragenden sendet)
lesson-close = Lektion schließen
    .tooltip = die Lektion verlassen; das Modell bleibt, wie es ist
lesson-next-lesson = nächste Lektion: { $title }
    .tooltip = die nächste Lektion, „{ $title }“, beim ersten Schritt öffnen (Bild ab)
lesson-last = der letzte Schritt der letzten Lektion

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = Last p = P l/k
axis-largest-angle = größtes |φ_i| über einen Zyklus (rad)
axis-damping-level = Dämpfung g2 = c2 / √(k m l²)
axis-mass-ratio = Massenverhältnis m1 / (Masse jenseits von Gelenk A)
axis-log-scale = { $axis } (logarithmisch)
axis-first-critical-load = erste kritische Last p
mark-load = Last
locus-far-left = { $name }: Eigenwerte bis hinab zu Re λ = { $re } 1/s (schnell abklingende Moden) liegen links der Ansicht, die jene zeigt, die über die Stabilität entscheiden
legend-branch-colour = Farbe der Zweige: die Last, p = { $from } bis { $to }
legend-eigenvalues-now = Eigenwerte bei der aktuellen Last
legend-measured = gemessen aus dem Lauf
legend-current-load = aktuelle Last
legend-overlay-no-change = kein Stabilitätswechsel bis zum Ende des Reglers
legend-overlay = Vergleich { $name }: { $loads }
legend-transition = p = { $load }: { $from } zu { $to }
legend-more-loads = { $count ->
    [one] { $count } weitere kritische Last (zieglerlab critical listet sie)
   *[other] { $count } weitere kritische Lasten (zieglerlab critical listet sie)
}
legend-no-analysis = keine Analyse
legend-stronger = kräftiger: schnelleres Anwachsen oder Abklingen (am stärksten: { $largest } 1/s)
legend-critical-loads = kritische Lasten
legend-now = jetzt
legend-now-off = jetzt: außerhalb der Karte ({ $why })
legend-now-no-value = jetzt: nicht auf der Karte ({ $axis } hat für diese Säule keinen Wert)
legend-now-below = { $name } = { $value } liegt unter { $bound }
legend-now-above = { $name } = { $value } liegt über { $bound }
legend-this-model = dieses Modell: p = { $load }
legend-straight-stable = gerade Säule, stabil
legend-straight-unstable = gerade Säule, instabil
legend-stable-cycle = stabiler Grenzzyklus
legend-unstable-cycle = instabiler Grenzzyklus
legend-hopf-point = Flatterbeginn (Hopf-Punkt)
legend-cycle-fold = LPC: Falte der Zyklen
legend-cycle-period-doubling = PD: Periodenverdopplung
legend-cycle-torus = NS: Torus (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC: Symmetriebruch (Verzweigungspunkt der Zyklen)
legend-sweep-up = Durchlauf aufwärts (ein Lauf)
legend-sweep-down = Durchlauf abwärts (ein Lauf)
legend-seen-in-ramp = während der Rampe gesehen
legend-largest-angle = größter Winkel dieses Laufs, letzte Periode
legend-flutter-soft = Flatterbeginn, weich: ein kleines Schwingen wächst
legend-flutter-hard = Flatterbeginn, hart: Sprung auf ein großes Schwingen
legend-divergence-onset = Divergenzbeginn
legend-special-points = B: Bautin (weich wird hart), BT: Bogdanov-Takens, DH: doppelter Hopf, ZH: Null-Hopf
legend-fold-of-cycles = Falte der Zyklen: darunter hält sich kein Schwingen
legend-hysteresis = Hysterese: Ruhe und großes Schwingen beide stabil
describe-against = { $y } über { $x }
describe-range = { $state } von { $from } bis { $to }
describe-ranges = Bereiche: { $ranges }
describe-mark = { $name } bei { $x }
describe-marked = markiert: { $marks }
describe-point = { $name } bei ({ $x }, { $y })
describe-points = benannt: { $points }
describe-bands = getönt zwischen einer Falte der Zyklen und einem harten Flatterbeginn: das Band der Hysterese, in dem Ruhe und großes Schwingen beide stabil sind
describe-curves = { $count ->
    [one] { $count } Kurve
   *[other] { $count } Kurven
}
describe-now-stable = bei der aktuellen Last liegen alle { $count } Eigenwerte links der imaginären Achse: ein Stoß klingt ab
describe-now-flutter = bei der aktuellen Last liegen { $right } von { $count } Eigenwerten rechts der imaginären Achse, { $oscillating } davon abseits der reellen Achse: ein Schwingen wächst (Flattern)
describe-now-divergence = bei der aktuellen Last liegen { $right } von { $count } Eigenwerten rechts der imaginären Achse, keiner abseits der reellen Achse: die Säule biegt aus (Divergenz)
describe-map = eine Karte aus { $columns } mal { $rows } Zellen: stabil { $stable } %, Flattern { $flutter } %, Divergenz { $divergence } %

## The scene, the load bar and the tabs' own words

scene-name = die Säule
scene-swing = ihr Ausschlag jetzt { $rad } rad
scene-hidden = die Säule, { $swing }
scene-analysing = die Säule, { $swing }; ihre Stabilität wird analysiert
scene-stable = stabil: ein Stoß klingt ab, auf ein Hundertstel in { $secs } s; { $swing }
scene-undamped = stabil, aber ungedämpft: ein Stoß schwingt weiter, weder wachsend noch abklingend; { $swing }
scene-flutter = die Säule flattert: ein Schwingen wächst, verdoppelt sich alle { $secs } s bei { $frequency } rad/s; { $swing }
scene-divergence = Divergenz: die Säule biegt aus der Geraden aus, verdoppelt sich alle { $secs } s; { $swing }
scene-stopped = der Lauf ist angehalten: { $status }; R startet einen neuen Lauf
scene-drag-hint = die Spitze oder ein Gelenk ziehen, um die Säule auszulenken
scene-whole-reach = ganzer Bereich
    .tooltip = den ganzen Kreis zeigen, den die Spitze erreichen kann, ruhend; aus: die Ansicht folgt der Bewegung, zoomt sofort heraus, wenn die Säule weit schwingt, und wieder herein, wenn sie sich beruhigt, immer mit der Einspannung im Bild
scene-delta =
    .tooltip = δ: der Winkel von der Richtung des letzten Stabes (der gestrichelte Pfeil, wohin eine ideale Folgelast zeigen würde) zur Kraft, die die Reibung des Bandes tatsächlich aufbringt (der durchgezogene Pfeil), als Bogen an der Spitze gezeichnet. δ = 0 ist eine perfekte Folgelast; die Rolle dreht die Kraft um δ, während sie seitlich auf dem Band gleitet (Gl. 23)
scene-stick-slip = Haftgleiten: die Gleitgeschwindigkeit liegt unter 1e-4 m/s; die Coulomb-Reibung ist hier regularisiert, außerhalb der Gültigkeit des Modells
scene-band = Band läuft nach links mit V = { $speed } m/s
load-bar = Last{"\u000A"}p = { $load }
    .name = Lastregler
    .tooltip = die Last p = P l/k: hier klicken oder ziehen, oder die Pfeiltasten nutzen (mit dem Regler im Fokus: links und rechts, Umschalt für zehn Schritte, Pos1 und Ende)
load-bar-said = Last p = { $load } von 0 bis { $end }
load-bar-said-hidden = { $load }: der Zustand ist verborgen, bis die Lektion ihn auflöst
load-bar-said-analysing = { $load }: wird analysiert
load-bar-said-range = { $load }: { $state }, von p = { $from } bis { $to }
load-bar-said-beyond = { $load }: jenseits des analysierten Bereichs
view-hint = ziehen: verschieben · Strg+Scrollen: zoomen · Doppelklick: einpassen
    .more = Alle Daten wieder zeigen (wie ein Doppelklick auf ein Diagramm).{"\u000A"}Ziehen oder scrollen zum Verschieben, Strg+Scrollen zum Zoomen, mit der rechten Taste einen Rahmen ziehen, um hineinzuzoomen.
view-fit = einpassen
map-readout-growth = Anwachsrate { $rate } 1/s
map-kick-settles = ein Stoß klingt ab
map-kick-hysteresis = ein kleiner Stoß klingt ab, ein großer lässt es schwingen (Hysterese)
map-kick-grows-softly = ein Stoß wächst sanft zu einem kleinen Schwingen
map-kick-jumps = ein Stoß springt auf ein großes Schwingen
map-following = Flattergrenze und Falten der Zyklen werden verfolgt…
map-not-followed = Grenzen nicht verfolgt: { $why }
map-readout-hint = auf die Karte zeigen, um eine Zelle abzulesen; klicken übernimmt ihre Last und ihren Parameter
histories-delta = δ: der Winkel der Bandkraft zu Stab 2
histories-energy = kinetische + Federenergie
histories-band-power = Leistung des Bandes
histories-rod-2 = Stab 2
zoom-outside = Zoom { $zoom } liegt außerhalb von { $least } bis { $most }: auf { $held } gesetzt (Strg+0: 100%)
plot-name = Diagramm: { $y } über { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Die Wurzelortskurve dieser Parameter wird berechnet...
locus-none = Keine Wurzelortskurve für diese Parameter.
locus-none-why = Keine Wurzelortskurve für diese Parameter: { $why }.
locus-title = Wurzelortskurve, p = { $from } bis { $to }
map-rows = Zeilen { $done } von { $total }
map-grey-rows = graue Zeilen haben keine Analyse: { $why }
map-empty-range = der Kartenbereich { $lo } bis { $hi } ist leer
map-no-thread = kein Thread für die Karte: { $why }
map-stopped = die Karte wurde angehalten: { $why }
map-axis = Last p über
    .tooltip = der zweite Parameter der Karte (sein Bereich unten startet die Karte neu)
map-from = von
    .name = Kartenbereich von
    .tooltip = wo der zweite Parameter beginnt
map-to = bis
    .name = Kartenbereich bis
    .tooltip = wo der zweite Parameter endet
paradox-computing = die Flatterlasten werden berechnet, während die Dämpfung verschwindet ...
paradox-joints = Die Flatterlast mit Gelenkdämpfern c1 = (c1/c2) c2, wenn das Dämpfungsniveau g2 = c2 / sqrt(k m l^2) gegen null geht: Der Grenzwert hängt vom Verhältnis ab und liegt unter der ungedämpften Last (Ziegler-Paradoxon).
paradox-external = Die Flatterlast mit gleichen Gelenkdämpfern c1 = c2 = c (innere Dämpfung) und dem Widerstand c_ext = (c_ext l^3 / c) c / l^3 längs der Stäbe (äußere Dämpfung), wenn das Niveau g2 = c / sqrt(k m l^2) gegen null geht: Auch äußere Dämpfung destabilisiert, und der Grenzwert hängt vom Verhältnis ab.
paradox-no-extent = die Kurven haben keine Ausdehnung entlang des Verhältnisses
paradox-no-thread = kein Thread für die Kurven: { $why }
paradox-dead-load = Eine Totlast (eta = 0) ist konservativ: Sie flattert nie, also gibt es kein Paradoxon zu zeigen.
paradox-stable-throughout = Keine Kurve zu zeichnen: Bei jedem gezeigten Verhältnis bleibt die Säule bis p = { $end } stabil.
paradox-failed = Keine Kurve zu zeichnen: { $why }.
paradox-kind = verschwindende Dämpfung:
paradox-kind-joints = Gelenkdämpfer
    .tooltip = die Gelenkdämpfer c1 und c2 im Verhältnis c1/c2
paradox-kind-external = äußerer Widerstand und innere
    .tooltip = Widerstand c_ext längs der Stäbe (äußere) und gleiche Gelenkdämpfer c1 = c2 = c (innere) im Verhältnis c_ext l^3 / c
paradox-roller = Die Last, bei der die Säule mit Rolle zuerst ihre Stabilität verliert, über der Masse der Rolle, für drei Bandgeschwindigkeiten (die Gleitdämpfung ist mu R / V).
paradox-roller-falling = fallen gegen null, wenn nu -> 0
paradox-roller-flat = fallen über diesen Bereich nicht gegen null
paradox-roller-massless = ; die masselose Rolle (die ideale Folgelast) verliert ihre Stabilität bei p = { $load }
paradox-roller-caption = { $intro } Bei der kleinsten gezeigten Masse, nu = { $nu }, stehen die Kurven bei { $at }, { $trend }{ $massless }.
record-next = die nächsten
record-secs = s nach
    .name = Sekunden der Aufnahme
    .tooltip = Sekunden des Fensters, die aufgenommen werden (1 bis 60)
record-folder =
    .name = Ordner der Aufnahme
    .tooltip = der Ordner, in den das GIF kommt
record-choosing = wird gewählt...
record-choose = wählen...
    .tooltip = den Ordner im Dialog der Arbeitsumgebung wählen
    .title = zieglerlab: der Ordner für Aufnahmen
record-start = aufnehmen
    .tooltip = aufnehmen, was das Fenster zeigt, 10 Bilder pro Sekunde, als GIF
    .no-folder = den Ordner gibt es nicht

## A lesson's revealed results

reveal-never = die Säule verliert ihre Stabilität bis p = { $load } nicht
reveal-theory = die Theorie: instabil ab p = { $load }
reveal-seen = ; die Bewegung zeigte sich bei p = { $load }
reveal-predicted = Deine Vorhersage war p = { $load };{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Richtig: Du hast „{ $chosen }“ gewählt, die Antwort.
reveal-wrong = Nicht diese: Du hast „{ $chosen }“ gewählt; die Antwort ist „{ $answer }“.
reveal-answer = Die Antwort: „{ $answer }“.
reveal-no-answer = die Theorie hat bei dieser Last keine Antwort
reveal-period = , eine Periode von { $secs } s
reveal-flutter = Flattern: Das Schwingen verdoppelt sich alle { $secs } s{ $period }
reveal-divergence = Divergenz: Die Neigung verdoppelt sich alle { $secs } s
reveal-stable = stabil: Ein Stoß halbiert sich alle { $secs } s{ $period }
reveal-undamped = stabil: Ein Stoß wächst weder, noch klingt er ab{ $period }
reveal-here = Die Theorie bei p = { $load }: { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = Stäbe = { $rods }: Der Lastregler reicht jetzt von 0 bis { $end }, und die Last ist mit ihm von p = { $from } nach { $to } gewandert (dieselbe Stelle auf dem Regler; eine andere Last eintippen)
notice-rods-load-kept = Stäbe = { $rods }: Die Last p = { $load } bleibt ({ $why })
notice-switched-to-reference = die Säule ist zu steif für den Integrator rapier mit seinem Schritt von 1/240 s (riesige Dämpfung oder Steifigkeit bei wenig Masse); auf den Referenzintegrator umgeschaltet
notice-lesson-last-step = das war der letzte Schritt der Lektion: sie schließen oder eine andere aus dem Menü Lektionen öffnen
notice-paste-nothing = nichts einzufügen: zuerst Einstellungstext kopieren („Einstellungen kopieren“ im Menü teilen) oder ihn in das Feld tippen
notice-paste-not-understood = eingefügte Einstellungen abgelehnt, nichts geändert: { $what } nicht verstanden
notice-pasted = Einstellungen eingefügt
notice-not-saved = nicht gespeichert: keine Datei gewählt (wo sich kein Dialog öffnete, bietet diese Arbeitsumgebung keinen an)
recording-saved = Aufnahme gespeichert unter { $path }: { $frames } Bilder in { $secs } s{ $slow }
recording-jerky = ; sie hat nur { $caught } Bilder pro Sekunde von den { $fps } pro Sekunde des GIFs erfasst (die Erfassungsrate: der Rechner war zu beschäftigt für mehr), also läuft das GIF im richtigen Tempo, aber ruckelig: ein kleineres Fenster (oder der Beamermodus aus) nimmt mehr auf
recording-title = { $title }: Aufnahme, noch { $secs } s
recording-making = das GIF entsteht: Bild { $done } von { $kept }
save-as = speichern unter
    .path = Pfad zum Speichern
save-as-typed = Auf dieser Arbeitsumgebung öffnete sich kein Dateidialog: Tippe, wohin { $what } gespeichert werden soll.
save-as-exists = { $path } gibt es schon: ersetzen? (zum Ersetzen nochmals speichern)
save-as-replace = ersetzen
save-as-save = speichern
save-as-cancel = abbrechen
save-as-what-table = die Tabelle (CSV)
save-as-what-plots = die Diagramme (PNG)
save-as-no-path = einen Dateipfad eingeben
save-as-no-folder = sein Ordner existiert nicht
save-as-folder = das ist ein Ordner: einen Dateinamen darin eingeben
save-as-pipe = das ist eine Pipe oder ein Gerät, keine Datei: einen Dateipfad eingeben
save-as-protected = die Datei existiert und darf nicht geschrieben werden ({ $why }); sie bleibt, wie sie ist

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (äußere / innere)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = Dämpfung g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds }: eine Kurve, die erste kritische Last hängt nicht von V ab
paradox-reference-undamped = ungedämpft
paradox-reference-massless = nu = 0: die ideale Folgelast
paradox-reference = { $name }: p = { $load }
paradox-reference-above = { $name }: p = { $load } (über der Achse)

## Refused values and the engine's failures

refused-value = { $subject } = { $value }: { $allowed }
refused-not-a-number = „{ $text }“ ist keine Zahl
refused-unknown-preset = unbekannte Vorgabe „{ $name }“; die Vorgaben sind: { $known }
refused-unknown-key = unbekannter Schlüssel „{ $key }“; die Schlüssel sind: { $known }
refused-malformed = „{ $text }“ ist nicht Schlüssel=Wert mit einer Zahl (z. B. load=2.5): { $reason }
refused-conflict = { $first } und { $second } setzen dieselbe Größe; nur eines angeben
allowed-finite = muss eine endliche Zahl sein
allowed-positive = muss > 0 sein
allowed-non-negative = muss >= 0 sein
allowed-key-range = muss eine endliche Zahl { $range } { $unit } sein
allowed-key-count = muss eine ganze Zahl { $range } sein
allowed-between = muss zwischen { $min } und { $key } = { $max } liegen
allowed-rods = muss eine ganze Zahl von 2 bis { $most } sein
allowed-eta-range = muss zwischen 0 (Totlast) und 1 (Folgelast) liegen
allowed-frictionless-band = muss > 0 sein: Ohne Reibung übt das Band überhaupt keine Last aus (für eine unbelastete Säule die Last auf 0 setzen)
allowed-friction-too-small = zu klein: Die Last p = { $load } bräuchte eine Normalkraft R = P / mu jenseits jeder Zahl
allowed-beyond-analysis = jenseits dessen, was die Analyse quadrieren kann (Größen { $smallest } bis { $largest })
allowed-makes-beyond-analysis = bringt { $what } jenseits dessen, was die Analyse quadrieren kann (Größen { $smallest } bis { $largest })
allowed-masses-too-unequal = die Massen sind zu ungleich: Die Determinante der Massenmatrix liegt unter 1e-12 ihrer Größenordnung, also entscheidet die Rundung über die Bewegung (z. B. eine Spitzenmasse oder Rolle über etwa dem 1e12-Fachen der Stäbe)
allowed-mass-missing = die Säule braucht Masse jenseits des Gelenks A (Stab 2, Spitze oder Rolle) und Masse oder Trägheit, die sich mit Stab 1 allein bewegt; die Massenmatrix ist singulär
allowed-chain-massless = eine Kette braucht Masse oder Trägheit auf jeder Kopie von Stab 2 (m2 oder I2 > 0): Mit masselosem Stab 2 ist die Massenmatrix der Kette singulär
allowed-needs-damped-joint2 = braucht ein gedämpftes Gelenk 2: zuerst c2 > 0 (oder die Dämpfungsstufe) setzen
allowed-infinite-damper-ratio = c2 = 0 bei c1 > 0: Das zu haltende Verhältnis c1/c2 ist unendlich; zuerst c2 > 0 setzen
allowed-band-at-rest = muss für die lineare Analyse > 0 sein: Bei V = 0 ist die Coulombsche Reibung um die Ruhelage nicht differenzierbar (Haftgleiten)
allowed-roller-has-no-eta = die Rolle hat kein eta: Die Reibung des Bandes gibt die Richtung der Kraft vor, gegen das Gleiten am Kontakt, und ihr Winkel delta zu Stab 2 ist ein Ergebnis der Bewegung, kein Parameter
allowed-state-length = muss 2 (Stäbe + 1) sein: die Winkel, der Spin und ihre Geschwindigkeiten
allowed-time-step = muss ein Zeitschritt in (0, 1] s sein
quantity-load-force = die Last P
quantity-load-p = die Last p = P l/k
quantity-inertia-o = die Trägheit um O
quantity-inertia-coupling = die Koppelträgheit
quantity-inertia-a = die Trägheit um A
quantity-stiffness-k1 = die Steifigkeit k1
quantity-stiffness-k2 = die Steifigkeit k2
quantity-damper-c1 = der Dämpfer c1
quantity-damper-c2 = der Dämpfer c2
quantity-drag = der Widerstand c_ext l^3
quantity-slip-damping = die Gleitdämpfung mu R l^2 / V
quantity-spin-inertia = die Drehträgheit der Rolle m3 r^2 / 2
quantity-mass-matrix = die Massenmatrix
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = die Länge des Zustands
quantity-time-step = dt
engine-too-stiff = die rapier-Engine kann diese Säule bei dt = { $step } s nicht integrieren: Ihre Federn und Dämpfer erreichen Raten von { $rate } 1/s, die dt < { $need } s brauchen; die Referenz-Engine verwenden
engine-rapier-world = die rapier2d-Welt ließ sich für diese Säule nicht aufbauen (ihre Gelenke wurden abgelehnt); die Referenz-Engine verwenden
analysis-not-converged = die Eigenwertiteration konvergierte bei der Last p = { $load } nicht
ramp-refused-end = { $end } = { $value }: muss eine Last p >= 0 sein
ramp-refused-rate = Rampenrate = { $value }: muss eine positive Last pro Sekunde sein
ramp-refused-too-slow = Rampenrate = { $value }: muss mindestens { $slowest } Last pro Sekunde sein (langsamer bewegte sich die Last tagelang nicht sichtbar)
ramp-refused-too-long = die Rampe von { $from } bis { $to } mit { $rate } pro Sekunde dauert { $secs } s simulierte Zeit; höchstens { $most } s (etwa vier Monate): eine schnellere Rate oder nähere Enden
ramp-refused-model = { $end } = { $value }: { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = Rampe: { $why }
notice-ramp-stopped = Rampe angehalten: { $why }
notice-map-point-refused = Karte: { $why }
notice-overlay-unavailable = Überlagerung nicht verfügbar: { $why }
notice-table-not-saved = nicht gespeichert: { $why }
notice-no-locus = für diese Parameter gibt es keine Wurzelortskurve
notice-no-thread = nicht gespeichert: kein Thread zum Schreiben ({ $why })
notice-saved-lines = { $count ->
    [one] { $count } Zeile
   *[other] { $count } Zeilen
} in { $path } gespeichert
notice-write-failed = nicht gespeichert: { $why }
notice-plots-saved = die Diagramme in { $path } gespeichert
notice-plots-not-saved = die Diagramme nicht gespeichert: { $why }
notice-recording-failed = Aufnahme fehlgeschlagen: { $why }
notice-layout-not-saved = Fensteranordnung nicht gespeichert: { $why }
notice-stored-overlay = die gespeicherte Überlagerung { $name } ist keine Vorgabe; keine Überlagerung
notice-stored-map-axis = die gespeicherte Kartenachse wird nicht verwendet: { $why }
notice-stored-language = die gespeicherte Sprache wird nicht verwendet: { $why }
notice-lesson-refused = Lektion { $name }: { $why }
notice-lesson-not-opened = Lektion nicht geöffnet: { $why }
notice-reset-closed-lesson = alles zurückgesetzt: Die Lektion „{ $title }“ ist geschlossen (im Lektionsmenü wieder öffnen)

## The post-critical tab's notes

cycles-computing = die Grenzzyklen werden von jedem Flatterbeginn an verfolgt ...
cycles-none = keine Grenzzyklen: { $why }
cycles-no-onset = kein Flatterbeginn im Bereich der Lastleiste: keine Grenzzyklen
cycles-chain-too-long = eine Kette aus { $rods } Stäben zu verfolgen dauert im Fenster zu lange (16 Stäbe brauchen auf zwei Kernen etwa 20 s, und die Arbeit wächst schneller als die Zahl der Stäbe); `zieglerlab bifurcation` berechnet ihre Zyklen auf der Kommandozeile
cycles-no-thread = kein Thread für die Zyklen: { $why }
cycles-branch = { $name }: { $onset } Einsatz bei p = { $at }; der Zweig endete: { $end }
cycles-offshoot = { $name }: asymmetrische Zyklen (und ihre Spiegelbilder) ab dem BPC bei p = { $at }; der Zweig endete: { $end }
cycles-onset-soft = weicher
cycles-onset-hard = harter
cycles-no-branch = Flatterbeginn bei p = { $at }: { $why }
cycles-no-branch-reversible = keine Dämpfung, eine reversible Säule: kein Grenzzyklus zu verfolgen
cycles-no-branch-degenerate = der erste Ljapunow-Koeffizient ist im Rahmen seiner Genauigkeit null; Zyklen nicht verfolgt
cycles-no-branch-not-converged = das Schießverfahren konvergierte nahe dem Einsatz nicht; keine Zyklen
cycles-end-left-range = hat den Lastbereich verlassen
cycles-end-large-amplitude = die Amplitude eines Winkels überschritt { $most } rad (die Säule schwingt herum)
cycles-end-long-period = die Periode wuchs über das { $most }-Fache der Periode am Einsatz
cycles-end-lost = das Schießverfahren konvergierte jenseits von p = { $load } nicht
cycles-end-stick-slip = der Kontakt der Rolle nähert sich jenseits von p = { $load } dem Haften auf dem Band (Haftgleiten: Die Reibung ist dort nicht glatt)
cycles-end-unresolved = die Zyklen jenseits von p = { $load } sind nicht aufgelöst (trivialer Multiplikator weicht um mehr als { $tolerance } von 1 ab)
cycles-end-point-limit = { $most } Zyklen berechnet
cycles-end-cancelled = auf Wunsch angehalten

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = die Stabilität ist nicht aufgelöst: Bei p = { $load } reichen die Moden von { $fastest } 1/s bis { $slowest } 1/s, ein Verhältnis über { $span }, also bleiben die Anwachsraten der langsamen Moden der Rundung überlassen (eine Mode, die weit schneller ist als die anderen, etwa der Spin einer Rolle mit winziger Masse nu)
not-resolved-slow-mode-lost = die Stabilität ist nicht aufgelöst: Bei p = { $load } reichen die Moden von { $scale } 1/s bis { $slowest } 1/s, also gehen Anwachsraten unter { $tolerance } 1/s in der Rundung verloren (das Modell ist nahe einem singulären Grenzfall: ein sehr langsames Band V oder sehr große Dämpfung)
not-resolved-methods-disagree = die Stabilität ist nicht aufgelöst: Bei p = { $load } sind sich die verfolgten Wurzeln und die Schur-Zerlegung über den Zustand uneins (die Rundung entscheidet: eine Mode, die weit schneller ist als die anderen, etwa der Spin einer Rolle mit winziger Masse nu); die gezeigten kritischen Lasten können falsch sein oder fehlen
not-resolved-rounding-decides = die Stabilität ist nicht aufgelöst: Für p von { $low } bis { $high } liegen die Anwachsraten zwischen 1e-12 und 1e-10 der Frequenzskala, wo die Rundung über den Zustand entscheidet (eine Rolle mit winziger Masse nu, deren schwaches Flattern proportional zu nu wächst, oder ein sehr langsames Band V); die gezeigten kritischen Lasten können verschoben sein oder fehlen
not-resolved-refinement-cut = die Wurzelortskurve wurde nur bis p = { $load } verfeinert: Dahinter sind die Zweige nur an den gleichmäßig verteilten Lasten abgetastet, also kann ein Fenster eines anderen Zustands fehlen, das schmaler ist als ihr Abstand (die Grenze der Verfeinerung für Zeit und Speicher wurde erreicht)

## The stored state's check before the window opens (a damaged store)

store-zoom = der Zoomfaktor { $zoom } (erlaubt 0.2 bis 5)
store-geometry = die Fenstergeometrie { $width } x { $height } Punkte bei Skalierung { $scale }
store-unreadable = der gespeicherte Zustand ließ sich nicht lesen ({ $why }); eine Kopie liegt unter { $copy }; es wird mit den Voreinstellungen begonnen
store-unreadable-uncopied = ließ sich weder lesen ({ $why }) noch kopieren ({ $error })
store-moved = der gespeicherte Zustand { $path } { $why }; er wird nach { $aside } verschoben, und die Voreinstellungen gelten
store-not-moved = der gespeicherte Zustand { $path } { $why } und ließ sich nicht beiseiteschieben ({ $error }); Einstellungen werden nicht gespeichert
store-folder-not-made = Einstellungen werden nicht gespeichert: Der Ordner { $folder } lässt sich nicht anlegen ({ $error })
store-folder-full = Einstellungen werden nicht gespeichert: Der Ordner { $folder } nimmt keine neue Datei auf ({ $error })
store-not-writable = Einstellungen werden nicht gespeichert: { $path } lässt sich nicht schreiben ({ $error })
store-is-folder = ist ein Ordner
store-is-device = ist ein Gerät, eine Pipe oder ein Socket
store-too-large = enthält { $bytes } Bytes (höchstens { $most } werden gelesen)
store-entry = { $why } (eframes Eintrag „{ $key }“)
store-ignored = gespeicherter Zustand: ignoriert { $what }
store-ignored-not-rewritten = gespeicherter Zustand: ignoriert { $what } (die Datei ließ sich nicht neu schreiben: { $error })
store-settings-unreadable = die gespeicherten Einstellungen ließen sich nicht lesen
store-original-kept = das Original liegt unter { $copy }
store-original-lost = vom Original ließ sich keine Kopie behalten ({ $error })
store-settings-partly = gespeicherte Einstellungen: ignoriert { $what }; der Rest bleibt
store-settings-ignored = gespeicherte Einstellungen ignoriert ({ $why }); es wird mit den Voreinstellungen begonnen
layout-ignored = gespeicherte Fensteranordnung ignoriert ({ $why }); die Standardanordnung gilt
notice-paste-unreadable = eingefügte Einstellungen nicht verstanden, nichts geändert: { $why }
notice-paste-refused = eingefügte Einstellungen abgelehnt, nichts geändert: { $why }
notice-analysis-unavailable = Analyse nicht verfügbar: { $why }
notice-lesson-step = Lektionsschritt { $step }: { $why }
notice-lesson = Lektion: { $why }
