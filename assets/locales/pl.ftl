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
legend-cycle-fold = LPC: fałda cykli
legend-cycle-period-doubling = PD: podwojenie okresu
legend-cycle-torus = NS: torus (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC: złamanie symetrii (punkt rozgałęzienia cykli)
legend-sweep-up = przejście w górę (jedna symulacja)
legend-sweep-down = przejście w dół (jedna symulacja)
legend-seen-in-ramp = widziane podczas rampy
legend-largest-angle = największy kąt tej symulacji, ostatni okres
legend-flutter-soft = początek flatteru, łagodny: rośnie małe drganie
legend-flutter-hard = początek flatteru, gwałtowny: skok do dużego drgania
legend-divergence-onset = początek dywergencji
legend-special-points = B: Bautin (łagodny staje się gwałtowny), BT: Bogdanov-Takens, DH: podwójny Hopf, ZH: zero-Hopf
legend-fold-of-cycles = fałda cykli: poniżej żadne drganie nie przetrwa
legend-hysteresis = histereza: spoczynek i duże drganie oba stabilne
describe-against = { $y } w funkcji { $x }
describe-range = { $state } od { $from } do { $to }
describe-ranges = zakresy: { $ranges }
describe-mark = { $name } przy { $x }
describe-marked = zaznaczone: { $marks }
describe-point = { $name } w punkcie ({ $x }, { $y })
describe-points = nazwane punkty: { $points }
describe-bands = zabarwione między fałdą cykli a gwałtownym początkiem flatteru: pas histerezy, gdzie spoczynek i duże drganie są oba stabilne
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
map-kick-settles = pchnięcie wygasa
map-kick-hysteresis = małe pchnięcie wygasa, duże zostawia drganie (histereza)
map-kick-grows-softly = pchnięcie łagodnie rośnie do małego drgania
map-kick-jumps = pchnięcie skacze do dużego drgania
map-following = śledzenie granicy flatteru i fałd cykli…
map-not-followed = granice nie śledzone: { $why }
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
map-empty-range = zakres mapy od { $lo } do { $hi } jest pusty
map-no-thread = brak wątku dla mapy: { $why }
map-stopped = mapa zatrzymała się: { $why }
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
paradox-no-thread = brak wątku dla krzywych: { $why }
paradox-dead-load = Obciążenie martwe (eta = 0) jest zachowawcze: nigdy nie wywołuje flatteru, więc nie ma paradoksu do pokazania.
paradox-stable-throughout = Brak krzywej do narysowania: przy każdym pokazanym stosunku kolumna pozostaje stateczna do p = { $end }.
paradox-failed = Brak krzywej do narysowania: { $why }.
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
save-as-no-path = wpisz ścieżkę pliku
save-as-no-folder = jej folder nie istnieje
save-as-folder = to jest folder: wpisz w nim nazwę pliku
save-as-pipe = to jest potok lub urządzenie, nie plik: wpisz ścieżkę pliku
save-as-protected = plik istnieje i nie wolno go zapisać ({ $why }); pozostaje bez zmian

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

## Refused values and the engine's failures

refused-value = { $subject } = { $value }: { $allowed }
refused-not-a-number = „{ $text }” nie jest liczbą
refused-unknown-preset = nieznane ustawienie „{ $name }”; ustawienia to: { $known }
refused-unknown-key = nieznany klucz „{ $key }”; klucze to: { $known }
refused-malformed = „{ $text }” nie jest postaci klucz=wartość z liczbą (np. load=2.5): { $reason }
refused-conflict = { $first } i { $second } ustawiają tę samą wielkość; podaj tylko jedno
allowed-finite = musi być liczbą skończoną
allowed-positive = musi być > 0
allowed-non-negative = musi być >= 0
allowed-key-range = musi być liczbą skończoną { $range } { $unit }
allowed-key-count = musi być liczbą całkowitą { $range }
allowed-between = musi leżeć między { $min } a { $key } = { $max }
allowed-rods = musi być liczbą całkowitą od 2 do { $most }
allowed-eta-range = musi leżeć między 0 (obciążenie martwe) a 1 (siła śledząca)
allowed-frictionless-band = musi być > 0: bez tarcia taśma nie wywiera żadnego obciążenia (dla nieobciążonej kolumny ustaw obciążenie na 0)
allowed-friction-too-small = za mały: obciążenie p = { $load } wymagałoby siły normalnej R = P / mu poza wszelką liczbą
allowed-beyond-analysis = poza tym, co analiza może podnieść do kwadratu (wielkości od { $smallest } do { $largest })
allowed-makes-beyond-analysis = wyprowadza { $what } poza to, co analiza może podnieść do kwadratu (wielkości od { $smallest } do { $largest })
allowed-masses-too-unequal = masy są zbyt nierówne: wyznacznik macierzy mas jest poniżej 1e-12 jej skali, więc o ruchu decyduje zaokrąglenie (np. masa na wierzchołku lub rolka ponad około 1e12 razy cięższa od prętów)
allowed-mass-missing = kolumna potrzebuje masy za przegubem A (pręt 2, wierzchołek lub rolka) oraz masy lub bezwładności poruszającej się z samym prętem 1; macierz mas jest osobliwa
allowed-chain-massless = łańcuch potrzebuje masy lub bezwładności na każdej kopii pręta 2 (m2 lub I2 > 0): przy nieważkim pręcie 2 macierz mas łańcucha jest osobliwa
allowed-needs-damped-joint2 = wymaga tłumionego przegubu 2: najpierw ustaw c2 > 0 (lub poziom tłumienia)
allowed-infinite-damper-ratio = c2 = 0 przy c1 > 0: stosunek c1/c2 do utrzymania jest nieskończony; najpierw ustaw c2 > 0
allowed-band-at-rest = musi być > 0 dla analizy liniowej: przy V = 0 tarcie Coulomba nie jest różniczkowalne wokół spoczynku (stick-slip)
allowed-roller-has-no-eta = rolka nie ma eta: tarcie taśmy wyznacza kierunek siły, przeciwny do poślizgu w styku, a jej kąt delta względem pręta 2 jest wynikiem ruchu, nie parametrem
allowed-state-length = musi wynosić 2 (pręty + 1): kąty, obrót i ich prędkości
allowed-time-step = musi być krokiem czasowym w (0, 1] s
quantity-load-force = obciążenie P
quantity-load-p = obciążenie p = P l/k
quantity-inertia-o = bezwładność względem O
quantity-inertia-coupling = bezwładność sprzężenia
quantity-inertia-a = bezwładność względem A
quantity-stiffness-k1 = sztywność k1
quantity-stiffness-k2 = sztywność k2
quantity-damper-c1 = tłumik c1
quantity-damper-c2 = tłumik c2
quantity-drag = opór c_ext l^3
quantity-slip-damping = tłumienie poślizgu mu R l^2 / V
quantity-spin-inertia = bezwładność obrotu rolki m3 r^2 / 2
quantity-mass-matrix = macierz mas
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = długość stanu
quantity-time-step = dt
engine-too-stiff = silnik rapier nie może całkować tej kolumny przy dt = { $step } s: jej sprężyny i tłumiki osiągają szybkości { $rate } 1/s, które wymagają dt < { $need } s; użyj silnika odniesienia
engine-rapier-world = nie udało się zbudować świata rapier2d dla tej kolumny (jej przeguby zostały odrzucone); użyj silnika odniesienia
analysis-not-converged = iteracja wartości własnych nie zbiegła się przy obciążeniu p = { $load }
ramp-refused-end = { $end } = { $value }: musi być obciążeniem p >= 0
ramp-refused-rate = tempo rampy = { $value }: musi być dodatnim obciążeniem na sekundę
ramp-refused-too-slow = tempo rampy = { $value }: musi wynosić co najmniej { $slowest } obciążenia na sekundę (wolniej obciążenie nie poruszałoby się widocznie przez całe dni)
ramp-refused-too-long = rampa od { $from } do { $to } w tempie { $rate } na sekundę trwa { $secs } s czasu symulowanego; najwyżej { $most } s (około czterech miesięcy): szybsze tempo lub bliższe końce
ramp-refused-model = { $end } = { $value }: { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = rampa: { $why }
notice-ramp-stopped = rampa zatrzymana: { $why }
notice-map-point-refused = mapa: { $why }
notice-overlay-unavailable = nakładka niedostępna: { $why }
notice-table-not-saved = nie zapisano: { $why }
notice-no-locus = dla tych parametrów nie ma linii pierwiastkowych
notice-no-thread = nie zapisano: brak wątku do zapisu ({ $why })
notice-saved-lines = zapisano { $count ->
    [one] { $count } wiersz
    [few] { $count } wiersze
    [many] { $count } wierszy
   *[other] { $count } wiersza
} w { $path }
notice-write-failed = nie zapisano: { $why }
notice-plots-saved = zapisano wykresy w { $path }
notice-plots-not-saved = wykresów nie zapisano: { $why }
notice-recording-failed = nagrywanie nie powiodło się: { $why }
notice-layout-not-saved = nie zapisano układu okna: { $why }
notice-stored-overlay = zapisana nakładka { $name } nie jest ustawieniem; bez nakładki
notice-stored-map-axis = zapisana oś mapy nie jest używana: { $why }
notice-stored-language = zapisany język nie jest używany: { $why }
notice-lesson-refused = lekcja { $name }: { $why }
notice-lesson-not-opened = nie otwarto lekcji: { $why }
notice-reset-closed-lesson = zresetowano wszystko: lekcja „{ $title }” jest zamknięta (otwórz ją ponownie z menu lekcji)

## The post-critical tab's notes

cycles-computing = śledzenie cykli granicznych od każdego początku flatteru ...
cycles-none = brak cykli granicznych: { $why }
cycles-no-onset = brak początku flatteru w zakresie paska obciążenia: brak cykli granicznych
cycles-chain-too-long = śledzenie łańcucha { $rods } prętów trwa w oknie zbyt długo (16 prętów zajmuje około 20 s na dwóch rdzeniach, a praca rośnie szybciej niż liczba prętów); `zieglerlab bifurcation` oblicza jego cykle z wiersza poleceń
cycles-no-thread = brak wątku dla cykli: { $why }
cycles-branch = { $name }: { $onset } początek przy p = { $at }; gałąź zakończyła się: { $end }
cycles-offshoot = { $name }: cykle niesymetryczne (i ich odbicia lustrzane) od BPC przy p = { $at }; gałąź zakończyła się: { $end }
cycles-onset-soft = łagodny
cycles-onset-hard = gwałtowny
cycles-no-branch = początek flatteru przy p = { $at }: { $why }
cycles-no-branch-reversible = brak tłumienia, kolumna odwracalna: brak cyklu granicznego do śledzenia
cycles-no-branch-degenerate = pierwszy współczynnik Lapunowa jest zerowy w granicach swojej dokładności; cykli nie śledzono
cycles-no-branch-not-converged = metoda strzałów nie zbiegła się w pobliżu początku; brak cykli
cycles-end-left-range = wyszła poza zakres obciążeń
cycles-end-large-amplitude = amplituda kąta przekroczyła { $most } rad (kolumna obraca się dookoła)
cycles-end-long-period = okres wzrósł ponad { $most } razy okres na początku
cycles-end-lost = metoda strzałów nie zbiegła się powyżej p = { $load }
cycles-end-stick-slip = styk rolki zbliża się do przylgnięcia do taśmy powyżej p = { $load } (stick-slip: tarcie nie jest tam gładkie)
cycles-end-unresolved = cykle powyżej p = { $load } nie są rozstrzygnięte (trywialny mnożnik odbiega od 1 o więcej niż { $tolerance })
cycles-end-point-limit = obliczono { $most } cykli
cycles-end-cancelled = zatrzymano na żądanie

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = stateczność nie jest rozstrzygnięta: przy p = { $load } postacie drgań sięgają od { $fastest } 1/s do { $slowest } 1/s, stosunek ponad { $span }, więc szybkości narastania wolnych postaci zależą od zaokrągleń (postać znacznie szybsza od innych, jak obrót rolki o znikomej masie nu)
not-resolved-slow-mode-lost = stateczność nie jest rozstrzygnięta: przy p = { $load } postacie drgań sięgają od { $scale } 1/s do { $slowest } 1/s, więc szybkości narastania poniżej { $tolerance } 1/s giną w zaokrągleniach (model jest blisko granicy osobliwej: bardzo wolna taśma V lub bardzo duże tłumienie)
not-resolved-methods-disagree = stateczność nie jest rozstrzygnięta: przy p = { $load } śledzone pierwiastki i rozkład Schura nie zgadzają się co do stanu (rozstrzyga zaokrąglenie: postać znacznie szybsza od innych, jak obrót rolki o znikomej masie nu); pokazane obciążenia krytyczne mogą być pozorne lub może ich brakować
not-resolved-rounding-decides = stateczność nie jest rozstrzygnięta: dla p od { $low } do { $high } szybkości narastania leżą między 1e-12 a 1e-10 skali częstości, gdzie o stanie decyduje zaokrąglenie (rolka o znikomej masie nu, której słaby flatter rośnie proporcjonalnie do nu, lub bardzo wolna taśma V); pokazane obciążenia krytyczne mogą być przesunięte lub może ich brakować
not-resolved-refinement-cut = linie pierwiastkowe zagęszczono tylko do p = { $load }: dalej gałęzie są próbkowane jedynie w równo rozłożonych obciążeniach, więc może brakować okna innego stanu węższego niż ich odstęp (osiągnięto limit czasu i pamięci zagęszczania)

## The stored state's check before the window opens (a damaged store)

store-zoom = współczynnik powiększenia { $zoom } (dozwolone od 0.2 do 5)
store-geometry = geometria okna { $width } x { $height } punktów w skali { $scale }
store-unreadable = nie udało się odczytać zapisanego stanu ({ $why }); kopia jest w { $copy }; start z ustawieniami domyślnymi
store-unreadable-uncopied = nie dał się odczytać ({ $why }) ani skopiować ({ $error })
store-moved = zapisany stan { $path } { $why }; zostaje przeniesiony do { $aside } i obowiązują ustawienia domyślne
store-not-moved = zapisany stan { $path } { $why } i nie dał się przenieść ({ $error }); ustawienia nie będą zapisywane
store-folder-not-made = ustawienia nie będą zapisywane: nie można utworzyć folderu { $folder } ({ $error })
store-folder-full = ustawienia nie będą zapisywane: folder { $folder } nie przyjmuje nowego pliku ({ $error })
store-not-writable = ustawienia nie będą zapisywane: nie można zapisać { $path } ({ $error })
store-is-folder = jest folderem
store-is-device = jest urządzeniem, potokiem lub gniazdem
store-too-large = zawiera { $bytes } bajtów (czyta się najwyżej { $most })
store-entry = { $why } (wpis „{ $key }” eframe)
store-ignored = zapisany stan: pominięto { $what }
store-ignored-not-rewritten = zapisany stan: pominięto { $what } (nie udało się zapisać pliku na nowo: { $error })
store-settings-unreadable = nie udało się odczytać zapisanych ustawień
store-original-kept = oryginał jest w { $copy }
store-original-lost = nie udało się zachować kopii oryginału ({ $error })
store-settings-partly = zapisane ustawienia: pominięto { $what }; reszta zachowana
store-settings-ignored = pominięto zapisane ustawienia ({ $why }); start z ustawieniami domyślnymi
layout-ignored = pominięto zapisany układ okna ({ $why }); obowiązuje układ domyślny
notice-paste-unreadable = wklejonych ustawień nie zrozumiano, nic nie zmieniono: { $why }
notice-paste-refused = wklejone ustawienia odrzucono, nic nie zmieniono: { $why }
notice-analysis-unavailable = analiza niedostępna: { $why }
notice-lesson-step = krok lekcji { $step }: { $why }
notice-lesson = lekcja: { $why }
