### zieglerlab: teksty okna po polsku.
###
### Te same komunikaty co en.ftl, z tymi samymi symbolami zastępczymi;
### liczby przychodzą już zapisane, z kropką dziesiętną jak w wierszu poleceń.
###
### Słowniczek (wszędzie tak samo):
###   flutter: flatter (niestateczność dynamiczna)   divergence: dywergencja
###   follower force: siła śledząca                  dead load: obciążenie martwe
###   critical load: obciążenie krytyczne            root locus: linie pierwiastkowe
###   eigenvalue: wartość własna                     growth rate: szybkość narastania
###   damping: tłumienie                             limit cycle: cykl graniczny
###   Hopf bifurcation: bifurkacja Hopfa (łagodny / gwałtowny początek)
###   rod: pręt     column: kolumna                  spring: sprężyna skrętna
###   roller: rolka  moving band: ruchoma taśma      friction: tarcie
###   stability map: mapa stateczności               Ziegler's paradox: paradoks Zieglera
###   stable: stateczny (stateczność konstrukcji, nie „stabilność”)

## Counts

rods-count = { $count ->
    [one] { $count } pręt
    [few] { $count } pręty
   *[many] { $count } prętów
}

## The sidebar's heading and its menus

menu-share = udostępnij
    .tooltip = ustawienia jako tekst: skopiuj je albo wklej
menu-record = nagraj
    .tooltip = nagraj okno do pliku GIF
menu-keys = klawisze
    .tooltip = polecenia klawiatury
menu-language = język okna (zapamiętany do następnego uruchomienia)
projector-toggle = projektor (P)
overlay = porównanie
    .none = brak
    .tooltip = linie pierwiastkowe innego modelu na szaro, przy tym samym a (jak rys. 8 stawia kolumnę idealną obok rolki)
section-parameters = parametry

## The status line at the window's foot

status-dismiss = zamknij
    .tooltip = usuń ten komunikat
status-latest = ostatni komunikat (cały tekst)
status-got-it = rozumiem
    .tooltip = ukryj wskazówkę
status-ready = gotowe
hint-first-launch = Przeciągnij suwak obciążenia do około 3 i naciśnij K, aby pchnąć kolumnę (spacja wstrzymuje).

## The tabs

tab-locus = linie pierwiastkowe
    .tooltip = linie pierwiastkowe: wartości własne kolumny na płaszczyźnie zespolonej i w funkcji obciążenia. Na lewo od osi pionowej ruch zanika, na prawo rośnie; wysokość to częstość. Flatter zaczyna się tam, gdzie para przecina oś
tab-histories = przebiegi czasowe
    .tooltip = kąty, energia i moc taśmy w czasie ruchu
tab-map = mapa stateczności
    .tooltip = stateczność przy każdym obciążeniu w funkcji drugiego parametru
tab-paradox = paradoks
    .tooltip = pierwsze obciążenie krytyczne, gdy tłumienie (albo masa rolki) zanika
tab-post-critical = zakrytycznie
    .tooltip = po początku flatteru: amplituda cykli granicznych w funkcji obciążenia, stabilnych lub nie, i wychylenie samej poruszającej się kolumny
save-png = zapisz PNG...
    .tooltip = te wykresy jako obraz, bez przycisków i wskazówek
save-csv = zapisz CSV...
    .tooltip = liczby tych wykresów, w kolumnach wiersza poleceń, do pliku
answer-hidden = Ten wykres pokazuje odpowiedź: wróci, gdy lekcja ją odsłoni.
answer-hidden-histories = { answer-hidden } Przebiegi czasowe pokazują, co robi kolumna.
tab-in-column-place = Karta „{ $tab }” jest w miejscu kolumny; karta linie pierwiastkowe przywraca kolumnę.
locus-beside-column = Linie pierwiastkowe są obok kolumny; wybrana tu karta pojawi się w miejscu kolumny.
plots-need-room = Wykresy potrzebują tu więcej miejsca: wyższego okna albo wyłączonego trybu projektora (P).

## The welcome of a first launch

welcome-title = Witaj w zieglerlab
welcome-column = Dwa pręty na sprężynach stoją utwierdzone na jednym końcu. Na drugim końcu siła naciska wzdłuż ostatniego pręta i obraca się razem z nim: to siła śledząca. Tu powstaje jak w laboratorium, dzięki rolce ciągniętej przez ruchomą taśmę.
welcome-states = Przy małych obciążeniach pchnięcie wywołuje drgania, które pozostają małe: kolumna jest stateczna. Powyżej obciążenia krytycznego pojawia się flatter: kolumna kołysze się w tę i z powrotem coraz szerzej. Przy jeszcze większych obciążeniach może nastąpić dywergencja: kolumna wygina się na bok bez drgań.
welcome-locus = Linie pierwiastkowe pokazują liczbami (wartościami własnymi), jak porusza się kolumna, gdy obciążenie rośnie. Na lewo od osi pionowej drgania zanikają, na prawo rosną. Jak daleko w prawo, to szybkość narastania; jak wysoko, to częstość.
welcome-try = Przeciągnij suwak obciążenia i obserwuj oba: flatter kolumny zaczyna się przy obciążeniu, przy którym wartości własne przecinają oś.
welcome-first-lesson = zacznij pierwszą lekcję
    .tooltip = kilka kroków: przewidź, gdzie zaczyna się flatter, a potem patrz
welcome-explore = odkrywam sam
    .tooltip = zamknij; lekcje zostają na górze paska bocznego
