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
