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
    .name = język: { $language }
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

## States and critical loads

state-stable = stateczność
state-flutter = flatter
state-divergence = dywergencja
transition = p = { $load }: { $from } -> { $to }
transition-meaning = p = { $load }: kolumna przechodzi od stanu „{ $from }” do stanu „{ $to }”; { $how }
    .to-flutter = powyżej tego obciążenia para wartości własnych leży na prawo od osi urojonej: pchnięcie przechodzi w coraz większe drgania
    .to-divergence = powyżej tego obciążenia rzeczywista wartość własna jest dodatnia: kolumna odchyla się bez drgań
    .to-stable = powyżej tego obciążenia żadna wartość własna nie leży na prawo od osi urojonej: pchnięcie już nie narasta
duration-forever = nigdy
duration-days = { $count ->
    [one] { $n } dzień
    [few] { $n } dni
    [many] { $n } dni
   *[other] { $n } dnia
}
duration-years = { $count ->
    [one] { $n } rok
    [few] { $n } lata
    [many] { $n } lat
   *[other] { $n } roku
}

## The model and the engine

model = model
    .source = { $source }: gdzie model znajduje się w pracy, za którą idzie ten program (jej rysunek i równania)
preset-ziegler-1952 = Ziegler 1952
    .description = Kolumna Zieglera: nieważkie pręty, masa skupiona 2m w przegubie A i m na końcu, idealna siła śledząca
preset-uniform-rods = rys. 1a
    .description = Jednorodne sztywne pręty o masie m (rys. 1a), idealna siła śledząca
preset-midpoint-masses = rys. 1b, równ. 1-7
    .description = Nieważkie pręty z masą skupioną m w środku każdego (rys. 1b, równ. 1-7), idealna siła śledząca
preset-roller = rys. 7, równ. 8-38
    .description = Jednorodne pręty z rolką ciągniętą przez ruchomą taśmę (rys. 7, równ. 8-38), spójna bezwładność obrotu; parametry z rys. 8
preset-roller-as-printed = równ. 39, rys. 8
    .description = Model z rolką jak wydrukowany w równ. (39): bezwładność obrotu pomnożona przez r/l2, błąd w pracy; parametry z rys. 8
preset-tabletop = tempo wykładu
    .description = Kolumna wielkości biurka na wykład: jednorodne pręty 25 cm i 100 g, sprężyny 0.0625 N m/rad (a = 10 1/s^2), idealna siła śledząca; powyżej p = 2.54 wpada we flatter z okresem około 1.5 s
preset-tabletop-roller = tempo wykładu
    .description = Kolumna biurkowa pchana rolką 10 g o promieniu 2.5 cm na taśmie poruszającej się z prędkością 0.1 m/s (nu = rho = mu = 0.1): słaby flatter od p = 0.024, który narasta minutami, silny blisko obciążenia kolumny idealnej
preset-beck = Beck 1952, łańcuch 16 prętów
    .description = Kolumna Becka jako łańcuch 16 jednorodnych prętów ze sprężynami k w każdym przegubie (belka o EI = k l, L = 16 l), siła śledząca: flatter przy P L^2/EI = 18.78 (ciągła kolumna Becka: 20.05)
preset-pflueger = kolumna Pflügera, łańcuch 16 prętów
    .description = Kolumna Pflügera: łańcuch Becka z 16 prętów z masą na końcu równą połowie masy kolumny, siła śledząca: masa na końcu obniża obciążenie flatteru do P L^2/EI = 15.06
preset-beck-roller = łańcuch Becka obciążony jak u Bigoniego i in. 2018
    .description = Łańcuch Becka z 16 prętów obciążony rolką na ruchomej taśmie (parametry bezwymiarowe pracy na każdym pręcie: masa rolki 0.1 m, promień 0.1 l, mu = 0.1, V = 0.1 m/s): tłumienie przez poślizg wywołuje słaby flatter od P L^2/EI = 0.025 (narastanie poniżej 3e-4 1/s) i silny od około 18.8, gdzie flatter ma łańcuch z siłą śledzącą
preset-pflueger-roller = łańcuch Pflügera obciążony jak u Bigoniego i in. 2018
    .description = Łańcuch Pflügera z 16 prętów (masa na końcu równa połowie masy prętów) obciążony tą samą rolką na ruchomej taśmie: słaby flatter od P L^2/EI = 0.008 (narastanie poniżej 4e-5 1/s), silny od 15.06, gdzie flatter ma łańcuch z siłą śledzącą
tip-force-dead = siła na końcu: obciążenie martwe (eta = 0), o stałym kierunku, zamiast siły śledzącej modelu
tip-force-partial = siła na końcu: częściowo styczna, obrócona o eta = { $eta } kąta ostatniego pręta (siła śledząca modelu ma eta = 1)
engine = całkowanie
    .tooltip = co całkuje ruch: symulacja biegnie dalej od miejsca, w którym jest
engine-rapier = rapier
    .tooltip = rapier: silnik fizyczny rapier2d, pręty jako bryły sztywne połączone przegubami (układ wieloczłonowy), obrót rolki niejawnie
engine-reference = wzorcowe
    .tooltip = adaptacyjna metoda Dormanda-Prince'a 5(4) na dokładnych równaniach

## The load

load-field = obciążenie p = P l/k
    .tooltip = wpisz obciążenie (Enter zatwierdza, Escape przywraca); także poza końcem suwaka
    .meaning = obciążenie bezwymiarowe: siła P na końcu razy długość pręta l przez sztywność sprężyn k (kolumna Zieglera ma flatter od p = 2.09)
roller-load = rolka: q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = własne obciążenie rolki: siła R dociskająca ją do taśmy, w jednostkach p; tarcie taśmy pcha siłą μ R, więc p = μ q
notes-more = ... i jeszcze { $count } (najedź)
load-beyond-range = p = { $load } leży poza rysowanym zakresem (od 0 do { $end }); stan poniżej dotyczy p
critical-loads-hidden = Obciążenia krytyczne są ukryte, dopóki lekcja ich nie odsłoni.
not-resolved = stateczność nie jest tu rozstrzygnięta (najedź, by zobaczyć dlaczego)
ramp-visible = koniec wychylony o { $percent }% długości
ramp-theory = teoria (biały znacznik): niestateczna od p = { $load }
ramp-seen = widziane (znacznik): ruch widoczny przy p = { $load } ({ $visible })
ramp-seen-late = widziane (znacznik): ruch widoczny przy p = { $load }, z opóźnieniem: najedź, by zobaczyć dlaczego ({ $visible })
    .why = Pojawia się z opóźnieniem: po przekroczeniu progu ruch potrzebuje czasu, by urosnąć do widocznej wielkości, a rampa w tym czasie idzie dalej. Wolniejsza rampa pokazuje go bliżej teorii.
ramp-watching = czekam, aż ruch stanie się widoczny ({ $visible })

## The parameters

groups = parametry bezwymiarowe
    .tooltip = kilka kombinacji wartości SI, które decydują o ruchu (a = k/(m l^2) ustala, jak jest szybki; nu, rho, mu i V rolki jej masę, rozmiar, tarcie i prędkość taśmy); zmiana jednego zachowuje pozostałe
si-parameters = parametry SI
mu-moves-load = (R stałe: zmienia p)
key-allowed = { $description } (dozwolone: { $range })
refused = odrzucone: { $why }
key-load = obciążenie p = P l/k na wspólnej osi (P = mu R dla rolki; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2): ustala k1 (i k2 w tym samym stosunku), zachowuje p
    .range = > 0
key-nu = nu = m3/m, masa rolki przez masę pręta
    .range = >= 0
key-rho = rho = r/l, promień rolki przez długość pręta
    .range = w (0, l2/l]
key-mu = współczynnik tarcia; do równań wchodzi tylko mu R, więc R pozostaje stałe, a obciążenie p = mu R l/k się zmienia
    .range = > 0
key-V = prędkość taśmy (porusza się w stronę -x); analiza liniowa wymaga V > 0
    .range = >= 0
key-l1 = długość pręta 1 (jego rozkład masy skaluje się razem z nią)
    .range = > 0
key-l2 = długość pręta 2 (jego rozkład masy skaluje się razem z nią)
    .range = > 0
key-m1 = masa pręta 1 wraz z masami skupionymi na nim (rozkład zachowany)
    .range = >= 0
key-m2 = masa pręta 2 (rozkład zachowany)
    .range = >= 0
key-s1 = środek masy pręta 1, od utwierdzenia O
    .range = w [0, l1]
key-s2 = środek masy pręta 2, od przegubu A
    .range = w [0, l2]
key-I1 = moment bezwładności pręta 1 względem środka masy
    .range = >= 0
key-I2 = moment bezwładności pręta 2 względem środka masy
    .range = >= 0
key-m_tip = masa skupiona na końcu B (masa rolki to m3)
    .range = >= 0
key-k1 = sprężyna skrętna w utwierdzeniu O
    .range = > 0
key-k2 = sprężyna skrętna w przegubie A
    .range = > 0
key-c1 = tłumik wiskotyczny w utwierdzeniu O
    .range = >= 0
key-c2 = tłumik wiskotyczny w przegubie A
    .range = >= 0
key-c_ext = zewnętrzny opór wiskotyczny wzdłuż obu prętów (opór powietrza, zlinearyzowany): siła na jednostkę długości równa c_ext razy lokalna prędkość poprzeczna pręta
    .range = >= 0
key-rods = pręty łańcucha: pręt 1, potem kopie pręta 2 ze sprężyną i tłumikiem przegubu A w każdym przegubie; masa końcowa i obciążenie na końcu ostatniego pręta
    .range = od 2 do 64
key-P = wartość siły na końcu
    .range = >= 0
key-eta = styczność siły na końcu: jej kierunek obraca się o eta razy kąt ostatniego pręta (1: siła śledząca, 0: obciążenie martwe)
    .range = w [0, 1]
key-m3 = masa rolki (0: nieważka, idealna siła śledząca)
    .range = >= 0
key-r = promień rolki
    .range = w (0, l2]
key-R = siła docisku rolki do taśmy
    .range = >= 0

## Time

command-play = start
    .running = pauza
    .tooltip = start / pauza
command-load-up = obciążenie w górę
    .tooltip = zwiększ obciążenie o setną część suwaka
command-load-down = obciążenie w dół
    .tooltip = zmniejsz obciążenie o setną część suwaka
command-kick = pchnij
    .tooltip = pchnięcie: każdy pręt obrócony o 0.03 rad
command-reset = od nowa
    .tooltip = od nowa: nowa symulacja od standardowego zaburzenia
command-reset-all = wszystko od nowa
    .tooltip = wszystko od nowa: parametry i obciążenie modelu, normalna prędkość, nowa symulacja, domyślne widoki; otwarta lekcja zostaje zamknięta
command-projector = tryb projektora
    .tooltip = tryb projektora: wysoki kontrast, duży tekst
command-next = dalej
    .tooltip = następny krok lekcji (pilot prezentera wysyła Page Down)
command-back = wstecz
    .tooltip = poprzedni krok lekcji (Page Up)
command-full-screen = pełny ekran
    .tooltip = pełny ekran: okno wypełnia ekran (ponownie, by wyjść)
command-step = krok
    .tooltip = jeden krok całkowania (1/240 s), potem pauza
key-space = spacja
key-right = w prawo
key-up = w górę
key-left = w lewo
key-down = w dół
key-page-down = Page Down
key-page-up = Page Up
focus-keys-tab = następny element (shift+tab: poprzedni)
    .keys = tab
focus-keys-ctrl-tab = następna karta (ctrl+shift+tab: poprzednia)
    .keys = ctrl+tab
focus-keys-press = gdy aktywny jest przycisk, pole wyboru, lista lub karta: naciśnij go (spacja uruchamia tylko, gdy nic nie jest aktywne)
    .keys = spacja, enter
focus-keys-slider = gdy aktywny jest suwak (obciążenia, przewidywania): przesuń o setną część; shift: o dziesiątą
    .keys = w lewo, w prawo
focus-keys-column = gdy aktywna jest kolumna (tab do niej): obróć ją o 0.02 rad w jedną lub drugą stronę, shift: 0.1 rad (przeciąganie z klawiatury)
    .keys = w lewo, w prawo
focus-keys-ends = gdy aktywny jest suwak obciążenia lub przewidywania: jego końce
    .keys = home, end
focus-keys-plot = gdy aktywny jest wykres (tab do niego): przesuń o dziesiątą część, powiększ wokół środka; enter: mapa przyjmuje komórkę pod krzyżykiem
    .keys = strzałki, +, -
focus-keys-escape = zwolnij aktywny element (pole tekstowe: cofnij wpisywanie)
    .keys = esc
focus-keys-others = Page Down, Page Up, K, R, P i w górę/w dół działają zawsze, poza edytowanym polem tekstowym
    .keys = pozostałe
pace-slow = Wolno
    .tooltip = ćwierć czasu rzeczywistego
pace-normal = Normalnie
    .tooltip = czas rzeczywisty: jedna symulowana sekunda na sekundę
pace-fast = Szybko
    .tooltip = cztery razy szybciej niż czas rzeczywisty
speed-factor = × prędkość
    .tooltip = symulowane sekundy na sekundę czasu zegarowego
run-time = t = { $secs } s   ({ $status })
run-paused = pauza
run-running = trwa
run-diverged = rozbieżna przy t = { $secs } s
run-too-stiff = zbyt sztywna dla całkowania wzorcowego przy t = { $secs } s: bardzo lekka rolka lub zatrzymana taśma (całkowanie rapier sobie z nimi radzi) albo obciążenie czy sztywność tak duże, że żaden krok nie rozdziela prędkości kolumny
run-too-fast = zbyt szybka dla całkowania rapier przy t = { $secs } s: kolumna obraca się z prędkością { $rate } rad/s, większą, niż rozdziela jego stały krok ({ $most } rad na krok); całkowanie wzorcowe za nią nadąża
run-lagging = biegnie { $achieved }x: ten komputer nie nadąża przy { $asked }x

## The status card

card-stable =
    .meaning = stateczna: małe pchnięcie pozostaje małe (zanika albo, bez żadnego tłumienia, zachowuje swoją wielkość)
card-flutter =
    .meaning = flatter: kolumna kołysze się w tę i z powrotem, coraz szerzej (para wartości własnych na prawo od osi)
card-divergence =
    .meaning = dywergencja: kolumna wygina się na bok bez drgań (rzeczywista wartość własna na prawo od osi)
card-weak-flutter = słaby flatter
    .meaning = słaby flatter: drgania rosną, ale o mniej niż 1% swojej częstości: powoli, przez wiele wahnięć
card-hidden = stateczna czy nie?
    .why = Werdykt jest ukryty, dopóki lekcja go nie odsłoni: obserwuj kolumnę.
card-no-figures = brak wartości stateczności: { $why }
card-growth = szybkość narastania  { $rate } 1/s
    .tooltip = szybkość narastania: jak szybko ruch rośnie (dodatnia) lub zanika (ujemna), na sekundę: część rzeczywista wartości własnej położonej najdalej na prawo
card-growth-zero = szybkość narastania  0 (z dokładnością do { $tolerance } 1/s)
card-not-resolved = nierozstrzygnięte przy tych parametrach: zobacz ostrzeżenie pod obciążeniem
card-e-folding = czas e-krotnego wzrostu  { $time }
    .tooltip = czas e-krotnego wzrostu: czas, w którym drgania rosną e = 2.72 razy (1 / szybkość narastania)
card-decay = czas zaniku  { $time }
    .tooltip = czas zaniku: czas, w którym drgania maleją e = 2.72 razy
card-neutral = obojętna: bez wzrostu i bez zaniku
card-mode = postać { $k } z { $n }
card-the-mode = postać
card-frequency = częstość  { $frequency } rad/s  (okres { $period } s{ $which })
    .tooltip = częstość: jak szybko kolumna drga, w radianach na sekundę (wysokość wartości własnej); okres to jedno pełne wahnięcie. Kolumna z n prętów ma n postaci drgań, liczonych tu od najwolniejszej; karta opisuje tę, która rośnie najszybciej (lub zanika najwolniej), a pomiar z symulacji jest pokazany dla tej samej postaci
card-non-oscillatory = bez drgań: dominująca wartość własna jest rzeczywista
card-measured = zmierzone z symulacji{ $mode }  { $measurement }
    .tooltip = wartość własna dopasowana do ruchu samej symulacji (pęk macierzy kątów): co najmniej 20 s małych drgań (poniżej 0.05 rad) od ostatniego pchnięcia, puszczenia lub zmiany, każda postać, gdy symulacja obejmuje jej cały okres; „postać 2 z 2” liczy postaci drgań kolumny od najwolniejszej. ± to niepewność samego dopasowania: jak daleko dopasowania do pierwszych i ostatnich trzech czwartych symulacji odbiegają od dopasowania do całej. Także krok czasowy dt całkowania oddala samą symulację od modelu liniowego, jej częstość o około ω³dt²/24
card-measured-other-mode = zmierzone z symulacji: tylko { $mode }, { $measurement } ({ $card } z karty w tej symulacji zbyt słaba do dopasowania)
card-measured-other = zmierzone z symulacji: tylko inna wartość własna, { $measurement } (ta z karty w tej symulacji zbyt słaba do dopasowania)
card-measured-after = pomiar: po 20 s ruchu o małej amplitudzie (|φ| < 0.05 rad)
card-measured-two-rods = pomiar: tylko dla dwóch prętów (wiele wolnych postaci łańcucha wymaga dłuższej symulacji, niż dopasowanie może wykorzystać)
card-measurement = narastanie { $growth } 1/s, częstość { $frequency } rad/s
card-measurement-unknown = narastanie { $growth } 1/s, częstość { $frequency } rad/s (niepewność nieznana: za mało okresów w symulacji)
card-grows-slowly = rośnie o { $percent } na okres: obserwuj minutami, nie sekundami
card-grows-too-slowly = rośnie o { $percent } na okres: zbyt wolno, by zobaczyć to na lekcji
onset-soft = łagodny początek przy p = { $at }: drgania ustalają się na cyklu granicznym, który rośnie od zera
onset-soft-roller = łagodny początek przy p = { $at }: cykl rośnie od zera, aż rolka zbliży się do przylgnięcia
onset-hard = gwałtowny początek przy p = { $at }: drgania skaczą na duży cykl, który trwa także poniżej progu
onset-degenerate = początek przy p = { $at } ani łagodny, ani gwałtowny w pierwszym rzędzie
onset-reversible = brak tłumienia: brak cyklu granicznego, na którym drgania mogłyby się ustalić (kolumna odwracalna)
    .tooltip = Bez tłumienia kolumna jest odwracalna: flatter zaczyna się tam, gdzie dwie pary wartości własnych spotykają się na osi urojonej, i nie ma atraktora, a więc nie ma cyklu granicznego, na którym drgania mogłyby się ustalić.
onset =
    .tooltip = Łagodny: po przekroczeniu progu drgania rosną od zera do małego ustalonego cyklu, większego przy rosnącym obciążeniu; gwałtowny: skaczą na duży cykl, który pozostaje, gdy obciążenie nieco się obniży. Przylgnięcie: rolka przestaje się ślizgać po taśmie, gdzie tarcie zmienia swoje prawo.{"\u000A"}{"\u000A"}Pierwszy współczynnik Lapunowa { $lyapunov } na progu p = { $at } (punkt Hopfa, częstość { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = W jego pobliżu |phi1| cyklu wynosi około { $a } sqrt(p - { $at }) rad.
onset-sticking = Na rolce poślizg w styku maleje, gdy cykl rośnie; gdzie zbliża się do zera, tarcie przestaje być gładkie i ruch przechodzi w stick-slip, którego ta analiza nie śledzi: gałąź na karcie zakrytycznie kończy się tam.

## The load ramp

ramp = rampa obciążenia
ramp-from = od
    .name = rampa od
    .tooltip = obciążenie, od którego rampa zaczyna
ramp-to = do
    .name = rampa do
    .tooltip = obciążenie, na którym rampa się zatrzymuje
ramp-rate = z
    .name = tempo rampy
    .tooltip = jak szybko zmienia się obciążenie, na symulowaną sekundę
ramp-start = start rampy
    .tooltip = obciążenie przechodzi do „od” i zmienia się do „do” w zadanym tempie, podczas gdy symulacja trwa (ręczne ustawienie obciążenia ją kończy)
ramp-pause = wstrzymaj rampę
    .tooltip = zatrzymaj obciążenie tam, gdzie jest; symulacja trwa dalej
ramp-resume = wznów
ramp-stop = zakończ
    .tooltip = zakończ rampę
ramp-done = gotowe
ramp-paused = wstrzymana
ramp-moving = trwa
ramp-progress = p = { $load } w stronę { $to } z tempem { $rate }/s ({ $doing })

## Sharing the settings

share-copy = kopiuj ustawienia
    .tooltip = model, obciążenie, całkowanie i prędkość jako tekst, do schowka i do pola poniżej
share-paste = wklej ze schowka
    .tooltip = przyjmij tekst ustawień skopiowany gdzie indziej (pole poniżej go pokaże)
share-box = albo wpisz lub wklej tu tekst ustawień
share-take = przyjmij tekst powyżej
    .tooltip = wczytaj ustawienia zapisane w polu
paste-too-long = wklejanie odrzucone, nic się nie zmieniło: tekst ma { $bytes } bajtów; żadne pole tutaj nie przyjmuje więcej niż { $most } (tekst ustawień ma poniżej 2000)
paste-no-text = wklej ustawienia: schowek nie zawiera tekstu (najpierw skopiuj tekst ustawień)

## Lessons

lessons = lekcje
lessons-built-in = wbudowana lekcja { $name }
lesson-file = plik lekcji
    .hint = plik lekcji (.ron)
    .tooltip = ścieżka do własnego pliku lekcji (format opisuje README)
lesson-open = otwórz
    .tooltip = wczytaj i sprawdź plik, potem go uruchom
lesson-reading = czytam { $path }
lesson-reading-stopped = { $path }: czytanie przerwane bez odpowiedzi
lesson-step = krok { $k } z { $n }
lesson-prediction = twoje przewidywanie: p = { $load }
lesson-predicted-load = przewidywane obciążenie
    .tooltip = gdzie się go spodziewasz; suwak obciążenia go zaznacza (klawisze jak na suwaku obciążenia: w lewo, w prawo, shift o dziesięć kroków, home, end)
lesson-back = wstecz
    .tooltip = poprzedni krok (Page Up)
lesson-next = dalej
    .tooltip = następny krok: ustawia i uruchamia to, co opisuje (Page Down, jak wysyła pilot prezentera)
lesson-close = zamknij lekcję
    .tooltip = wyjdź z lekcji; model zostaje taki, jaki jest
lesson-next-lesson = następna lekcja: { $title }
    .tooltip = otwórz następną lekcję, „{ $title }”, od pierwszego kroku (Page Down)
lesson-last = ostatni krok ostatniej lekcji

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = obciążenie p = P l/k
axis-largest-angle = największe |φ_i| w cyklu (rad)
axis-damping-level = tłumienie g2 = c2 / √(k m l²)
axis-mass-ratio = stosunek mas m1 / (masa za przegubem A)
axis-log-scale = { $axis } (skala logarytmiczna)
axis-first-critical-load = pierwsze obciążenie krytyczne p
mark-load = obciążenie
locus-far-left = { $name }: wartości własne aż do Re λ = { $re } 1/s (szybko zanikające postaci) leżą na lewo od widoku, który obejmuje te decydujące o stateczności
legend-branch-colour = kolor gałęzi: obciążenie, p = od { $from } do { $to }
legend-eigenvalues-now = wartości własne przy bieżącym obciążeniu
legend-measured = zmierzone z symulacji
legend-current-load = bieżące obciążenie
legend-overlay-no-change = brak zmiany stateczności do końca suwaka
legend-overlay = porównanie { $name }: { $loads }
legend-transition = p = { $load }: { $from } w { $to }
legend-more-loads = { $count ->
    [one] jeszcze { $count } obciążenie krytyczne (zieglerlab critical je wymienia)
    [few] jeszcze { $count } obciążenia krytyczne (zieglerlab critical je wymienia)
   *[many] jeszcze { $count } obciążeń krytycznych (zieglerlab critical je wymienia)
}
legend-no-analysis = brak analizy
legend-stronger = mocniej: szybsze narastanie lub zanik (najmocniej: { $largest } 1/s)
legend-critical-loads = obciążenia krytyczne
legend-now = teraz
legend-now-off = teraz: poza mapą ({ $why })
legend-now-no-value = teraz: nie na mapie ({ $axis } nie ma wartości dla tej kolumny)
legend-now-below = { $name } = { $value } jest poniżej { $bound }
legend-now-above = { $name } = { $value } jest powyżej { $bound }
legend-this-model = ten model: p = { $load }
legend-straight-stable = prosta kolumna, stateczna
legend-straight-unstable = prosta kolumna, niestateczna
legend-stable-cycle = stabilny cykl graniczny
legend-unstable-cycle = niestabilny cykl graniczny
legend-hopf-point = początek flatteru (punkt Hopfa)
legend-sweep-up = przejście w górę (jedna symulacja)
legend-sweep-down = przejście w dół (jedna symulacja)
legend-seen-in-ramp = widziane podczas rampy
legend-largest-angle = największy kąt tej symulacji, ostatni okres
describe-against = { $y } w funkcji { $x }
describe-range = { $state } od { $from } do { $to }
describe-ranges = zakresy: { $ranges }
describe-mark = { $name } przy { $x }
describe-marked = zaznaczone: { $marks }
describe-curves = { $count ->
    [one] { $count } krzywa
    [few] { $count } krzywe
   *[many] { $count } krzywych
}
describe-now-stable = przy bieżącym obciążeniu wszystkie wartości własne ({ $count }) leżą na lewo od osi urojonej: pchnięcie zanika
describe-now-flutter = przy bieżącym obciążeniu { $right } z { $count } wartości własnych leży na prawo od osi urojonej, { $oscillating } z nich poza osią rzeczywistą: drgania rosną (flatter)
describe-now-divergence = przy bieżącym obciążeniu { $right } z { $count } wartości własnych leży na prawo od osi urojonej, żadna poza osią rzeczywistą: kolumna się wygina (dywergencja)
describe-map = mapa { $columns } na { $rows } komórek: stateczność { $stable }%, flatter { $flutter }%, dywergencja { $divergence }%

## The scene, the load bar and the tabs' own words

scene-name = kolumna
scene-swing = jej wychylenie teraz { $rad } rad
scene-hidden = kolumna, { $swing }
scene-analysing = kolumna, { $swing }; jej stateczność jest analizowana
scene-stable = stateczna: pchnięcie zanika, do setnej części w { $secs } s; { $swing }
scene-undamped = stateczna, ale bez tłumienia: pchnięcie drga dalej, ani nie rośnie, ani nie zanika; { $swing }
scene-flutter = kolumna ma flatter: drgania rosną, podwajając się co { $secs } s przy { $frequency } rad/s; { $swing }
scene-divergence = dywergencja: kolumna wygina się z prostej, podwajając wychylenie co { $secs } s; { $swing }
scene-stopped = symulacja się zatrzymała: { $status }; R zaczyna nową
scene-drag-hint = przeciągnij koniec lub przegub, aby wychylić kolumnę
scene-whole-reach = cały zasięg
    .tooltip = pokaż cały krąg, do którego sięga koniec, nieruchomo; wyłączone: widok śledzi ruch, oddala się od razu, gdy kolumna szeroko się wychyla, i przybliża, gdy się uspokaja, zawsze z utwierdzeniem w kadrze
scene-delta =
    .tooltip = δ: kąt od kierunku ostatniego pręta (przerywana strzałka, tam wskazywałaby idealna siła śledząca) do siły, którą faktycznie wywiera tarcie taśmy (ciągła strzałka), narysowany jako łuk na końcu. δ = 0 to idealna siła śledząca; rolka obraca siłę o δ, ślizgając się bokiem po taśmie (równ. 23)
scene-stick-slip = stick-slip: prędkość poślizgu jest poniżej 1e-4 m/s; tarcie Coulomba jest tu regularyzowane, poza zakresem ważności modelu
scene-band = taśma porusza się w lewo z V = { $speed } m/s
load-bar = obciążenie{"\u000A"}p = { $load }
    .name = suwak obciążenia
    .tooltip = obciążenie p = P l/k: kliknij lub przeciągnij tutaj albo użyj strzałek (gdy suwak jest aktywny: w lewo i w prawo, shift o dziesięć kroków, home i end)
load-bar-said = obciążenie p = { $load } w zakresie od 0 do { $end }
load-bar-said-hidden = { $load }: stan jest ukryty, dopóki lekcja go nie odsłoni
load-bar-said-analysing = { $load }: trwa analiza
load-bar-said-range = { $load }: { $state }, od p = { $from } do { $to }
load-bar-said-beyond = { $load }: poza przeanalizowanym zakresem
view-hint = przeciągnij: przesuń · Ctrl+kółko: powiększ · dwuklik: dopasuj
    .more = Pokaż znów wszystkie dane (jak dwuklik na wykresie).{"\u000A"}Przeciągnij lub przewiń, by przesunąć, Ctrl+kółko, by powiększyć, przeciągnij prostokąt prawym przyciskiem, by go przybliżyć.
view-fit = dopasuj
map-readout-growth = szybkość narastania { $rate } 1/s
map-readout-hint = wskaż mapę, by odczytać komórkę; kliknij, by przyjąć jej obciążenie i parametr
histories-delta = δ: kąt siły taśmy względem pręta 2
histories-energy = energia kinetyczna + sprężyn
histories-band-power = moc od taśmy
histories-rod-2 = pręt 2
zoom-outside = powiększenie { $zoom } jest poza zakresem { $least }-{ $most }: ustawiono { $held } (Ctrl+0: 100%)
plot-name = wykres: { $y } w funkcji { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Obliczam linie pierwiastkowe dla tych parametrów...
locus-none = Brak linii pierwiastkowych dla tych parametrów.
locus-none-why = Brak linii pierwiastkowych dla tych parametrów: { $why }.
locus-title = linie pierwiastkowe, p = od { $from } do { $to }
map-rows = wiersze: { $done } z { $total }
map-grey-rows = szare wiersze nie mają analizy: { $why }
map-axis = obciążenie p względem
    .tooltip = drugi parametr mapy (jego zakres poniżej uruchamia mapę od nowa)
map-from = od
    .name = zakres mapy od
    .tooltip = gdzie zaczyna się drugi parametr
map-to = do
    .name = zakres mapy do
    .tooltip = gdzie kończy się drugi parametr
paradox-computing = obliczam obciążenia flatteru przy zanikającym tłumieniu ...
paradox-joints = Obciążenie flatteru z tłumikami w przegubach c1 = (c1/c2) c2, gdy poziom tłumienia g2 = c2 / sqrt(k m l^2) dąży do zera: granica zależy od stosunku i leży poniżej obciążenia bez tłumienia (paradoks Zieglera).
paradox-external = Obciążenie flatteru z równymi tłumikami w przegubach c1 = c2 = c (tłumienie wewnętrzne) i oporem c_ext = (c_ext l^3 / c) c / l^3 wzdłuż prętów (tłumienie zewnętrzne), gdy poziom g2 = c / sqrt(k m l^2) dąży do zera: tłumienie zewnętrzne też destabilizuje, a granica zależy od stosunku.
paradox-no-extent = krzywe nie mają rozpiętości wzdłuż stosunku
paradox-kind = zanikające tłumienie:
paradox-kind-joints = tłumiki w przegubach
    .tooltip = tłumiki w przegubach c1 i c2 w stosunku c1/c2
paradox-kind-external = opór zewnętrzny i wewnętrzne
    .tooltip = opór c_ext wzdłuż prętów (zewnętrzny) i równe tłumiki w przegubach c1 = c2 = c (wewnętrzne) w stosunku c_ext l^3 / c
paradox-roller = Obciążenie, przy którym kolumna z rolką najpierw traci stateczność, w funkcji masy rolki, dla trzech prędkości taśmy (tłumienie przez poślizg to mu R / V).
paradox-roller-falling = maleją do zera, gdy nu -> 0
paradox-roller-flat = nie maleją do zera w tym zakresie
paradox-roller-massless = ; nieważka rolka (idealna siła śledząca) traci stateczność przy p = { $load }
paradox-roller-caption = { $intro } Przy najmniejszej pokazanej masie, nu = { $nu }, krzywe są na poziomie { $at }, { $trend }{ $massless }.
record-next = najbliższe
record-secs = s do
    .name = sekundy nagrania
    .tooltip = ile sekund okna nagrać (od 1 do 60)
record-folder =
    .name = folder nagrania
    .tooltip = folder, do którego trafi GIF
record-choosing = wybieranie...
record-choose = wybierz...
    .tooltip = wybierz folder w oknie dialogowym pulpitu
    .title = zieglerlab: folder na nagrania
record-start = nagraj
    .tooltip = nagraj to, co pokazuje okno, 10 klatek na sekundę, do pliku GIF
    .no-folder = folder nie istnieje

## A lesson's revealed results

reveal-never = kolumna nie traci stateczności aż do p = { $load }
reveal-theory = teoria: niestateczna od p = { $load }
reveal-seen = ; ruch pojawił się przy p = { $load }
reveal-predicted = Przewidziałeś p = { $load };{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Dobrze: wybrałeś „{ $chosen }”, to jest odpowiedź.
reveal-wrong = Nie ta: wybrałeś „{ $chosen }”; odpowiedź to „{ $answer }”.
reveal-answer = Odpowiedź: „{ $answer }”.
reveal-no-answer = teoria nie ma odpowiedzi przy tym obciążeniu
reveal-period = , okres { $secs } s
reveal-flutter = flatter: drgania podwajają się co { $secs } s{ $period }
reveal-divergence = dywergencja: wychylenie podwaja się co { $secs } s
reveal-stable = stateczna: pchnięcie maleje o połowę co { $secs } s{ $period }
reveal-undamped = stateczna: pchnięcie ani nie rośnie, ani nie zanika{ $period }
reveal-here = Teoria przy p = { $load }: { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = pręty = { $rods }: suwak obciążenia obejmuje teraz od 0 do { $end }, a obciążenie przesunęło się razem z nim z p = { $from } na { $to } (to samo miejsce na suwaku; wpisz obciążenie, by ustawić inne)
notice-rods-load-kept = pręty = { $rods }: obciążenie p = { $load } pozostaje ({ $why })
notice-switched-to-reference = kolumna jest zbyt sztywna dla całkowania rapier z jego krokiem 1/240 s (ogromne tłumienie lub sztywność przy małej masie); przełączono na całkowanie wzorcowe
notice-lesson-last-step = to był ostatni krok lekcji: zamknij ją albo otwórz inną z menu lekcje
notice-paste-nothing = nie ma czego wkleić: najpierw skopiuj tekst ustawień („kopiuj ustawienia” w menu udostępnij) albo wpisz go w pole
notice-paste-not-understood = wklejone ustawienia odrzucone, nic się nie zmieniło: nie rozpoznano { $what }
notice-pasted = ustawienia wklejone
notice-not-saved = nie zapisano: nie wybrano pliku (gdzie nie otworzyło się okno dialogowe, ten pulpit go nie oferuje)
recording-saved = nagranie zapisane w { $path }: { $frames } klatek w { $secs } s{ $slow }
recording-jerky = ; uchwyciło tylko { $caught } klatek na sekundę z { $fps } na sekundę, z których składa się GIF (tempo przechwytywania: komputer był zbyt zajęty, by wziąć więcej), więc GIF odtwarza się we właściwym tempie, ale skokowo: mniejsze okno (lub wyłączony tryb projektora) nagrywa więcej
recording-title = { $title }: nagrywanie, zostało { $secs } s
recording-making = tworzenie GIF-a: klatka { $done } z { $kept }
save-as = zapisz jako
    .path = ścieżka zapisu
save-as-typed = Na tym pulpicie nie otworzyło się okno wyboru pliku: wpisz, gdzie zapisać { $what }.
save-as-exists = { $path } już istnieje: zastąpić? (zapisz ponownie, by zastąpić)
save-as-replace = zastąp
save-as-save = zapisz
save-as-cancel = anuluj
save-as-what-table = tabelę (CSV)
save-as-what-plots = wykresy (PNG)

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (zewnętrzne / wewnętrzne)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = tłumienie g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds }: jedna krzywa, pierwsze obciążenie krytyczne nie zależy od V
paradox-reference-undamped = bez tłumienia
paradox-reference-massless = nu = 0: idealna siła śledząca
paradox-reference = { $name }: p = { $load }
paradox-reference-above = { $name }: p = { $load } (nad osią)
