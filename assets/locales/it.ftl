### zieglerlab: i testi della finestra in italiano.
###
### Gli stessi messaggi di en.ftl, con gli stessi segnaposto; i numeri
### arrivano già scritti, con il punto decimale come nella riga di comando.
###
### Glossario (usato ovunque allo stesso modo):
###   flutter: flutter (instabilità dinamica)   divergence: divergenza
###   follower force: forza follower            dead load: carico fisso
###   critical load: carico critico             root locus: luogo delle radici
###   eigenvalue: autovalore                    growth rate: tasso di crescita
###   damping: smorzamento                      limit cycle: ciclo limite
###   Hopf bifurcation: biforcazione di Hopf (insorgenza dolce / brusca)
###   rod: asta     column: colonna             spring: molla rotazionale
###   roller: rotella  moving band: nastro in movimento   friction: attrito
###   stability map: mappa di stabilità         Ziegler's paradox: paradosso di Ziegler

## Counts

rods-count = { $count ->
    [one] { $count } asta
   *[other] { $count } aste
}

## The sidebar's heading and its menus

menu-share = condividi
    .tooltip = le impostazioni come testo: copiarle o incollarne
menu-record = registra
    .tooltip = registra la finestra in una GIF
menu-keys = tasti
    .tooltip = i comandi da tastiera
menu-language = la lingua della finestra (ricordata al prossimo avvio)
    .name = lingua: { $language }
projector-toggle = proiettore (P)
overlay = confronto
    .none = nessuno
    .tooltip = il luogo delle radici di un altro modello in grigio, allo stesso a (come la Fig. 8 affianca la colonna ideale alla rotella)
section-parameters = parametri

## The status line at the window's foot

status-dismiss = chiudi
    .tooltip = cancella questo messaggio
status-latest = l'ultimo messaggio (il testo intero)
status-got-it = capito
    .tooltip = nascondi il suggerimento
status-ready = pronto
hint-first-launch = Trascina la barra del carico fino a circa 3 e premi K per dare un colpetto alla colonna (lo spazio mette in pausa).

## The tabs

tab-locus = luogo delle radici
    .tooltip = il luogo delle radici: gli autovalori della colonna nel piano complesso e in funzione del carico. A sinistra dell'asse verticale un moto si smorza, a destra cresce; l'altezza è la frequenza. Il flutter inizia dove una coppia attraversa l'asse
tab-histories = storie temporali
    .tooltip = gli angoli, l'energia e la potenza del nastro durante la simulazione
tab-map = mappa di stabilità
    .tooltip = la stabilità di ogni carico al variare di un secondo parametro
tab-paradox = paradosso
    .tooltip = il primo carico critico quando lo smorzamento (o la massa della rotella) tende a zero
tab-post-critical = post-critico
    .tooltip = oltre l'inizio del flutter: l'ampiezza dei cicli limite in funzione del carico, stabili o no, e l'oscillazione della colonna in moto
save-png = salva PNG...
    .tooltip = questi grafici come immagine, senza pulsanti né suggerimenti
save-csv = salva CSV...
    .tooltip = i numeri dietro questi grafici, nelle colonne della riga di comando, in un file
answer-hidden = Questo grafico mostra la risposta: ritorna quando la lezione la rivela.
answer-hidden-histories = { answer-hidden } Le storie temporali mostrano che cosa fa la colonna.
tab-in-column-place = La scheda «{ $tab }» è al posto della colonna; la scheda luogo delle radici riporta la colonna.
locus-beside-column = Il luogo delle radici è accanto alla colonna; una scheda scelta qui appare al posto della colonna.
plots-need-room = Qui i grafici hanno bisogno di più spazio: una finestra più alta, o la modalità proiettore spenta (P).

## The welcome of a first launch

welcome-title = Benvenuti in zieglerlab
welcome-column = Due aste su molle sono incastrate a un estremo. All'altro estremo una forza spinge lungo l'ultima asta e ruota con essa: una forza follower. Qui è realizzata come in laboratorio, da una rotella trascinata da un nastro in movimento.
welcome-states = A carichi piccoli un colpetto produce un'oscillazione che resta piccola: la colonna è stabile. Oltre un carico critico va in flutter: oscilla avanti e indietro, sempre più ampia. A carichi ancora maggiori può divergere: si piega da un lato senza oscillare.
welcome-locus = Il luogo delle radici mostra come numeri (gli autovalori) come si muove la colonna mentre il carico cresce. A sinistra dell'asse verticale un'oscillazione si smorza; a destra cresce. Quanto a destra è il tasso di crescita, quanto in alto la frequenza.
welcome-try = Trascina la barra del carico e osserva entrambi: la colonna inizia il flutter al carico in cui gli autovalori attraversano l'asse.
welcome-first-lesson = inizia la prima lezione
    .tooltip = pochi passi: prevedi dove inizia il flutter, poi osserva
welcome-explore = esploro da solo
    .tooltip = chiudi; le lezioni restano in cima alla barra laterale

## States and critical loads

state-stable = stabile
state-flutter = flutter
state-divergence = divergenza
transition = p = { $load }: { $from } -> { $to }
transition-meaning = p = { $load }: la colonna passa da { $from } a { $to }; { $how }
    .to-flutter = oltre questo carico una coppia di autovalori sta a destra dell'asse immaginario: un colpetto diventa un'oscillazione sempre più ampia
    .to-divergence = oltre questo carico un autovalore reale è positivo: la colonna si inclina senza oscillare
    .to-stable = oltre questo carico nessun autovalore sta a destra dell'asse immaginario: un colpetto non cresce più
duration-forever = mai
duration-days = { $count ->
    [one] { $n } giorno
   *[other] { $n } giorni
}
duration-years = { $count ->
    [one] { $n } anno
   *[other] { $n } anni
}

## The model and the engine

model = modello
    .source = { $source }: dove si trova il modello nello studio che questo programma segue (figura ed equazioni)
preset-ziegler-1952 = Ziegler 1952
    .description = La colonna di Ziegler: aste prive di massa, massa puntiforme 2m nel giunto A e m in punta, forza follower ideale
preset-uniform-rods = Fig. 1a
    .description = Aste rigide omogenee di massa m (Fig. 1a), forza follower ideale
preset-midpoint-masses = Fig. 1b, eq. 1-7
    .description = Aste prive di massa con una massa puntiforme m a metà di ciascuna (Fig. 1b, eq. 1-7), forza follower ideale
preset-roller = Fig. 7, eq. 8-38
    .description = Aste omogenee con una rotella trascinata da un nastro in movimento (Fig. 7, eq. 8-38), inerzia di rotazione coerente; parametri della Fig. 8
preset-roller-as-printed = eq. 39, Fig. 8
    .description = Il modello della rotella come stampato nell'eq. (39): l'inerzia di rotazione moltiplicata per r/l2, un refuso dell'articolo; parametri della Fig. 8
preset-tabletop = ritmo da lezione
    .description = Una colonna da tavolo per una lezione: aste omogenee da 25 cm e 100 g, molle da 0.0625 N m/rad (a = 10 1/s^2), forza follower ideale; oltre p = 2.54 va in flutter con un periodo di circa 1.5 s
preset-tabletop-roller = ritmo da lezione
    .description = La colonna da tavolo spinta da una rotella da 10 g di raggio 2.5 cm su un nastro a 0.1 m/s (nu = rho = mu = 0.1): un flutter debole da p = 0.024 che impiega minuti a crescere, uno forte vicino al carico della colonna ideale
preset-beck = Beck 1952, una catena di 16 aste
    .description = La colonna di Beck come catena di 16 aste omogenee con molle k in ogni giunto (una trave con EI = k l, L = 16 l), forza follower: flutter a P L^2/EI = 18.78 (colonna continua di Beck: 20.05)
preset-pflueger = La colonna di Pflüger, una catena di 16 aste
    .description = La colonna di Pflüger: la catena di Beck di 16 aste con una massa in punta pari a metà della massa della colonna, forza follower: la massa in punta abbassa il carico di flutter a P L^2/EI = 15.06
preset-beck-roller = La catena di Beck caricata come in Bigoni et al. 2018
    .description = La catena di Beck di 16 aste caricata dalla rotella sul nastro in movimento (i gruppi dell'articolo su ogni asta: massa della rotella 0.1 m, raggio 0.1 l, mu = 0.1, V = 0.1 m/s): lo smorzamento dello strisciamento la porta in un flutter debole da P L^2/EI = 0.025 (crescita sotto 3e-4 1/s), e forte da circa 18.8, dove va in flutter la catena con forza follower
preset-pflueger-roller = La catena di Pflüger caricata come in Bigoni et al. 2018
    .description = La catena di Pflüger di 16 aste (massa in punta metà di quella delle aste) caricata dalla stessa rotella sul nastro in movimento: flutter debole da P L^2/EI = 0.008 (crescita sotto 4e-5 1/s), flutter forte da 15.06, dove va in flutter la catena con forza follower
tip-force-dead = forza in punta: un carico fisso (eta = 0), di direzione costante, al posto della forza follower del modello
tip-force-partial = forza in punta: in parte tangenziale, ruotata di eta = { $eta } volte l'angolo dell'ultima asta (la forza follower del modello ha eta = 1)
engine = integratore
    .tooltip = che cosa integra il moto: la simulazione prosegue da dove si trova
engine-rapier = rapier
    .tooltip = rapier: il motore fisico rapier2d, aste come corpi rigidi uniti da cerniere (un sistema multicorpo), la rotazione della rotella implicita
engine-reference = riferimento
    .tooltip = Dormand-Prince 5(4) adattivo sulle equazioni esatte

## The load

load-field = carico p = P l/k
    .tooltip = scrivi un carico (Invio applica, Esc ripristina); anche oltre la fine della barra
    .meaning = il carico adimensionale: la forza in punta P per la lunghezza dell'asta l diviso la rigidezza delle molle k (la colonna di Ziegler va in flutter da p = 2.09)
roller-load = rotella: q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = il carico proprio della rotella: la forza R che la preme sul nastro, nelle unità di p; l'attrito del nastro spinge con μ R, quindi p = μ q
notes-more = ... e altre { $count } (passa sopra)
load-beyond-range = p = { $load } è oltre l'intervallo tracciato (da 0 a { $end }); lo stato qui sotto è a p
critical-loads-hidden = I carichi critici sono nascosti finché la lezione non li rivela.
not-resolved = la stabilità qui non è risolta (passa sopra per il motivo)
ramp-visible = la punta spostata del { $percent }% della lunghezza
ramp-theory = teoria (segno bianco): instabile da p = { $load }
ramp-seen = visto (segno): moto visibile a p = { $load } ({ $visible })
ramp-seen-late = visto (segno): moto visibile a p = { $load }, in ritardo: passa sopra per il motivo ({ $visible })
    .why = Appare in ritardo: oltre l'inizio il moto ha bisogno di tempo per crescere fino a una misura visibile, e intanto la rampa va avanti. Una rampa più lenta lo mostra più vicino alla teoria.
ramp-watching = in attesa che il moto diventi visibile ({ $visible })

## The parameters

groups = gruppi adimensionali
    .tooltip = le poche combinazioni dei valori SI che decidono il moto (a = k/(m l^2) fissa quanto è veloce; nu, rho, mu e V della rotella la sua massa, dimensione, attrito e la velocità del nastro); cambiarne uno lascia gli altri
si-parameters = parametri SI
mu-moves-load = (R fisso: sposta p)
key-allowed = { $description } (ammesso: { $range })
refused = rifiutato: { $why }
key-load = carico p = P l/k sull'asse comune (P = mu R per la rotella; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2): fissa k1 (e k2 nello stesso rapporto), mantiene p
    .range = > 0
key-nu = nu = m3/m, massa della rotella su massa dell'asta
    .range = >= 0
key-rho = rho = r/l, raggio della rotella su lunghezza dell'asta
    .range = in (0, l2/l]
key-mu = coefficiente d'attrito; nelle equazioni entra solo mu R, quindi R resta fisso e il carico p = mu R l/k cambia
    .range = > 0
key-V = velocità del nastro (si muove verso -x); l'analisi lineare richiede V > 0
    .range = >= 0
key-l1 = lunghezza dell'asta 1 (la sua distribuzione di massa scala con essa)
    .range = > 0
key-l2 = lunghezza dell'asta 2 (la sua distribuzione di massa scala con essa)
    .range = > 0
key-m1 = massa dell'asta 1, comprese le masse puntiformi (distribuzione mantenuta)
    .range = >= 0
key-m2 = massa dell'asta 2 (distribuzione mantenuta)
    .range = >= 0
key-s1 = baricentro dell'asta 1, dall'incastro O
    .range = in [0, l1]
key-s2 = baricentro dell'asta 2, dal giunto A
    .range = in [0, l2]
key-I1 = momento d'inerzia dell'asta 1 rispetto al baricentro
    .range = >= 0
key-I2 = momento d'inerzia dell'asta 2 rispetto al baricentro
    .range = >= 0
key-m_tip = massa puntiforme in punta B (la massa della rotella è m3)
    .range = >= 0
key-k1 = molla rotazionale all'incastro O
    .range = > 0
key-k2 = molla rotazionale al giunto A
    .range = > 0
key-c1 = smorzatore viscoso all'incastro O
    .range = >= 0
key-c2 = smorzatore viscoso al giunto A
    .range = >= 0
key-c_ext = resistenza viscosa esterna lungo entrambe le aste (resistenza dell'aria, linearizzata): una forza per unità di lunghezza pari a c_ext per la velocità locale trasversale all'asta
    .range = >= 0
key-rods = aste della catena: l'asta 1, poi copie dell'asta 2 con la molla e lo smorzatore del giunto A in ogni giunto; la massa in punta e il carico all'estremo dell'ultima asta
    .range = da 2 a 64
key-P = intensità della forza in punta
    .range = >= 0
key-eta = tangenzialità della forza in punta: la sua direzione ruota di eta volte l'angolo dell'ultima asta (1: forza follower, 0: carico fisso)
    .range = in [0, 1]
key-m3 = massa della rotella (0: senza massa, la forza follower ideale)
    .range = >= 0
key-r = raggio della rotella
    .range = in (0, l2]
key-R = forza normale della rotella sul nastro
    .range = >= 0

## Time

command-play = avvia
    .running = pausa
    .tooltip = avvia / pausa
command-load-up = carico su
    .tooltip = alza il carico di un centesimo della barra
command-load-down = carico giù
    .tooltip = abbassa il carico di un centesimo della barra
command-kick = colpetto
    .tooltip = colpetto: ogni asta ruotata di 0.03 rad
command-reset = riavvia
    .tooltip = riavvia: una nuova simulazione dalla perturbazione standard
command-reset-all = ripristina tutto
    .tooltip = ripristina tutto: i parametri e il carico del modello, velocità normale, una nuova simulazione, le viste predefinite; una lezione aperta viene chiusa
command-projector = modalità proiettore
    .tooltip = modalità proiettore: contrasto alto, testo grande
command-next = avanti
    .tooltip = il passo successivo della lezione (il telecomando di un relatore invia Pagina giù)
command-back = indietro
    .tooltip = il passo precedente della lezione (Pagina su)
command-full-screen = schermo intero
    .tooltip = schermo intero: la finestra riempie lo schermo (di nuovo per uscire)
command-step = passo
    .tooltip = un passo dell'integratore (1/240 s), poi pausa
key-space = spazio
key-right = destra
key-up = su
key-left = sinistra
key-down = giù
key-page-down = pagina giù
key-page-up = pagina su
focus-keys-tab = il controllo successivo (maiusc+tab: il precedente)
    .keys = tab
focus-keys-ctrl-tab = la scheda successiva (ctrl+maiusc+tab: la precedente)
    .keys = ctrl+tab
focus-keys-press = con un pulsante, una casella, una scelta o una scheda a fuoco: premerlo (lo spazio avvia solo se nulla è a fuoco)
    .keys = spazio, invio
focus-keys-slider = con un cursore a fuoco (la barra del carico, la previsione): spostarlo di un centesimo; maiusc: un decimo
    .keys = sinistra, destra
focus-keys-column = con la colonna a fuoco (tab fino a lei): ruotarla di 0.02 rad in un verso o nell'altro, maiusc: 0.1 rad (il trascinamento da tastiera)
    .keys = sinistra, destra
focus-keys-ends = con la barra del carico o la previsione a fuoco: i suoi estremi
    .keys = home, fine
focus-keys-plot = con un grafico a fuoco (tab fino a lui): spostare di un decimo, ingrandire attorno al centro; invio: una mappa prende la cella sotto la croce
    .keys = frecce, +, -
focus-keys-escape = lasciare il fuoco (un campo di testo: annullare quanto scritto)
    .keys = esc
focus-keys-others = pagina giù, pagina su, K, R, P e su/giù funzionano qualunque cosa sia a fuoco, tranne un campo di testo in modifica
    .keys = gli altri
pace-slow = Lento
    .tooltip = un quarto del tempo reale
pace-normal = Normale
    .tooltip = tempo reale: un secondo simulato al secondo
pace-fast = Veloce
    .tooltip = quattro volte il tempo reale
speed-factor = × velocità
    .tooltip = secondi simulati per secondo di orologio
run-time = t = { $secs } s   ({ $status })
run-paused = in pausa
run-running = in corso
run-diverged = divergita a t = { $secs } s
run-too-stiff = troppo rigida per l'integratore di riferimento a t = { $secs } s: una rotella molto leggera o un nastro fermo (l'integratore rapier li gestisce), o un carico o una rigidezza così grandi che nessun passo risolve le velocità della colonna
run-too-fast = troppo veloce per l'integratore rapier a t = { $secs } s: la colonna ruota a { $rate } rad/s, più di quanto il suo passo fisso risolva ({ $most } rad per passo); l'integratore di riferimento la segue
run-lagging = in corso a { $achieved }x: questo computer non regge { $asked }x

## The status card

card-stable =
    .meaning = stabile: un piccolo colpetto resta piccolo (si smorza, o senza alcuno smorzamento mantiene la sua ampiezza)
card-flutter =
    .meaning = flutter: la colonna oscilla avanti e indietro, sempre più ampia (una coppia di autovalori a destra dell'asse)
card-divergence =
    .meaning = divergenza: la colonna si piega da un lato senza oscillare (un autovalore reale a destra dell'asse)
card-weak-flutter = flutter debole
    .meaning = flutter debole: l'oscillazione cresce, ma di meno dell'1% della sua frequenza: lentamente, in molte oscillazioni
card-hidden = stabile o no?
    .why = Il verdetto è nascosto finché la lezione non lo rivela: osserva la colonna.
card-no-figures = nessun dato di stabilità: { $why }
card-growth = tasso di crescita  { $rate } 1/s
    .tooltip = tasso di crescita: quanto in fretta il moto cresce (positivo) o si smorza (negativo), al secondo: la parte reale dell'autovalore più a destra
card-growth-zero = tasso di crescita  0 (entro { $tolerance } 1/s)
card-not-resolved = non risolto a questi parametri: vedi l'avviso sotto il carico
card-e-folding = tempo di e-folding  { $time }
    .tooltip = tempo di e-folding: il tempo in cui l'oscillazione cresce di un fattore e = 2.72 (1 / tasso di crescita)
card-decay = tempo di smorzamento  { $time }
    .tooltip = tempo di smorzamento: il tempo in cui l'oscillazione si riduce di un fattore e = 2.72
card-neutral = neutro: né crescita né smorzamento
card-mode = modo { $k } di { $n }
card-the-mode = il modo
card-frequency = frequenza  { $frequency } rad/s  (periodo { $period } s{ $which })
    .tooltip = frequenza: quanto in fretta oscilla la colonna, in radianti al secondo (l'altezza dell'autovalore); il periodo è un'oscillazione completa. Una colonna di n aste ha n modi di oscillazione, contati qui dal più lento; la scheda descrive quello che cresce più in fretta (o si smorza più lentamente), e la misura dalla simulazione è mostrata per lo stesso modo
card-non-oscillatory = non oscillatorio: l'autovalore dominante è reale
card-measured = misurato dalla simulazione{ $mode }  { $measurement }
    .tooltip = l'autovalore adattato al moto della simulazione stessa (un fascio di matrici degli angoli): almeno 20 s di piccole oscillazioni (sotto 0.05 rad) dall'ultimo colpetto, rilascio o modifica, ogni modo quando la simulazione ne contiene un periodo intero; «modo 2 di 2» conta i modi di oscillazione della colonna dal più lento. Il ± è l'incertezza propria dell'adattamento: quanto gli adattamenti sui primi e sugli ultimi tre quarti della simulazione si discostano da quello sull'intera. Anche il passo temporale dt dell'integratore allontana la simulazione dal modello lineare, la sua frequenza di circa ω³dt²/24
card-measured-other-mode = misurato dalla simulazione: solo { $mode }, { $measurement } ({ $card } della scheda troppo debole in questa simulazione per adattarlo)
card-measured-other = misurato dalla simulazione: solo un altro autovalore, { $measurement } (quello della scheda troppo debole in questa simulazione per adattarlo)
card-measured-after = misurato: dopo 20 s di moto di piccola ampiezza (|φ| < 0.05 rad)
card-measured-two-rods = misurato: solo per due aste (i molti modi lenti di una catena richiedono una simulazione più lunga di quella che un adattamento può usare)
card-measurement = crescita { $growth } 1/s, frequenza { $frequency } rad/s
card-measurement-unknown = crescita { $growth } 1/s, frequenza { $frequency } rad/s (incertezza ignota: troppo pochi periodi nella simulazione)
card-grows-slowly = cresce del { $percent } per periodo: osserva per minuti, non secondi
card-grows-too-slowly = cresce del { $percent } per periodo: troppo lento da vedere in una lezione
onset-soft = insorgenza dolce a p = { $at }: l'oscillazione si assesta su un ciclo limite che cresce da zero
onset-soft-roller = insorgenza dolce a p = { $at }: un ciclo cresce da zero, finché la rotella non è vicina all'aderenza
onset-hard = insorgenza brusca a p = { $at }: l'oscillazione salta su un ciclo ampio, che persiste sotto l'insorgenza
onset-degenerate = insorgenza a p = { $at } né dolce né brusca al primo ordine
onset-reversible = nessuno smorzamento: nessun ciclo limite su cui assestarsi (una colonna reversibile)
    .tooltip = Senza smorzamento la colonna è reversibile: il flutter inizia dove due coppie di autovalori si incontrano sull'asse immaginario, e non c'è alcun attrattore, quindi nessun ciclo limite su cui l'oscillazione possa assestarsi.
onset =
    .tooltip = Dolce: oltre l'insorgenza l'oscillazione cresce da zero fino a un piccolo ciclo stazionario, più ampio al crescere del carico; brusca: salta su uno ampio, che resta quando il carico viene abbassato di poco. Aderenza: la rotella smette di strisciare sul nastro, dove l'attrito cambia legge.{"\u000A"}{"\u000A"}Primo coefficiente di Ljapunov { $lyapunov } all'insorgenza p = { $at } (punto di Hopf, frequenza { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = Vicino a essa |phi1| del ciclo vale circa { $a } sqrt(p - { $at }) rad.
onset-sticking = Sulla rotella lo strisciamento al contatto diminuisce mentre il ciclo cresce; dove si avvicina a zero l'attrito non è più regolare e il moto diventa stick-slip, che questa analisi non segue: il ramo nella scheda post-critico finisce lì.

## The load ramp

ramp = rampa di carico
ramp-from = da
    .name = rampa da
    .tooltip = il carico da cui parte la rampa
ramp-to = a
    .name = rampa a
    .tooltip = il carico a cui si ferma la rampa
ramp-rate = con
    .name = velocità della rampa
    .tooltip = quanto in fretta cambia il carico, per secondo simulato
ramp-start = avvia rampa
    .tooltip = il carico va a «da» e si sposta verso «a» con la velocità data, mentre la simulazione prosegue (impostare il carico a mano la termina)
ramp-pause = pausa rampa
    .tooltip = tieni il carico dove si trova; la simulazione prosegue
ramp-resume = riprendi
ramp-stop = ferma
    .tooltip = termina la rampa
ramp-done = finita
ramp-paused = in pausa
ramp-moving = in corso
ramp-progress = p = { $load } verso { $to } a { $rate }/s ({ $doing })

## Sharing the settings

share-copy = copia impostazioni
    .tooltip = il modello, il carico, l'integratore e la velocità come testo, negli appunti e nella casella qui sotto
share-paste = incolla dagli appunti
    .tooltip = prendi il testo delle impostazioni copiato altrove (la casella qui sotto lo mostra)
share-box = oppure scrivi o incolla qui il testo delle impostazioni
share-take = usa il testo qui sopra
    .tooltip = carica le impostazioni scritte nella casella
paste-too-long = incolla rifiutato, nulla è cambiato: il testo ha { $bytes } byte; nessun campo qui ne accetta più di { $most } (il testo delle impostazioni è sotto 2000)
paste-no-text = incolla impostazioni: gli appunti non contengono testo (copia prima il testo delle impostazioni)

## Lessons

lessons = lezioni
lessons-built-in = la lezione integrata { $name }
lesson-file = file di lezione
    .hint = un file di lezione (.ron)
    .tooltip = il percorso di un tuo file di lezione (il formato è nel README)
lesson-open = apri
    .tooltip = leggi e controlla il file, poi avvialo
lesson-reading = lettura di { $path }
lesson-reading-stopped = { $path }: la lettura si è fermata senza risposta
lesson-step = passo { $k } di { $n }
lesson-prediction = la tua previsione: p = { $load }
lesson-predicted-load = carico previsto
    .tooltip = dove te lo aspetti; la barra del carico lo segna (tasti come sulla barra del carico: sinistra, destra, maiusc per dieci passi, home, fine)
lesson-back = indietro
    .tooltip = il passo precedente (Pagina su)
lesson-next = avanti
    .tooltip = il passo successivo: imposta e avvia ciò che dice (Pagina giù, come invia il telecomando di un relatore)
lesson-close = chiudi lezione
    .tooltip = esci dalla lezione; il modello resta com'è
lesson-next-lesson = lezione successiva: { $title }
    .tooltip = apri la lezione successiva, «{ $title }», al primo passo (Pagina giù)
lesson-last = l'ultimo passo dell'ultima lezione

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = carico p = P l/k
axis-largest-angle = massimo |φ_i| in un ciclo (rad)
axis-damping-level = smorzamento g2 = c2 / √(k m l²)
axis-mass-ratio = rapporto di masse m1 / (massa oltre il giunto A)
axis-log-scale = { $axis } (scala logaritmica)
axis-first-critical-load = primo carico critico p
mark-load = carico
locus-far-left = { $name }: autovalori fino a Re λ = { $re } 1/s (modi che si smorzano in fretta) stanno a sinistra della vista, che contiene quelli che decidono la stabilità
legend-branch-colour = colore dei rami: il carico, p = da { $from } a { $to }
legend-eigenvalues-now = autovalori al carico attuale
legend-measured = misurati dalla simulazione
legend-current-load = carico attuale
legend-overlay-no-change = nessun cambio di stabilità fino alla fine del cursore
legend-overlay = confronto { $name }: { $loads }
legend-transition = p = { $load }: da { $from } a { $to }
legend-more-loads = { $count ->
    [one] { $count } altro carico critico (zieglerlab critical li elenca)
   *[other] altri { $count } carichi critici (zieglerlab critical li elenca)
}
legend-no-analysis = nessuna analisi
legend-stronger = più intenso: crescita o smorzamento più rapidi (massimo: { $largest } 1/s)
legend-critical-loads = carichi critici
legend-now = ora
legend-now-off = ora: fuori dalla mappa ({ $why })
legend-now-no-value = ora: non sulla mappa ({ $axis } non ha valore per questa colonna)
legend-now-below = { $name } = { $value } è sotto { $bound }
legend-now-above = { $name } = { $value } è sopra { $bound }
legend-this-model = questo modello: p = { $load }
legend-straight-stable = colonna diritta, stabile
legend-straight-unstable = colonna diritta, instabile
legend-stable-cycle = ciclo limite stabile
legend-unstable-cycle = ciclo limite instabile
legend-hopf-point = inizio del flutter (punto di Hopf)
legend-cycle-fold = LPC: piega dei cicli
legend-cycle-period-doubling = PD: raddoppio del periodo
legend-cycle-torus = NS: toro (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC: rottura di simmetria (punto di diramazione dei cicli)
legend-sweep-up = scansione in salita (una simulazione)
legend-sweep-down = scansione in discesa (una simulazione)
legend-seen-in-ramp = visto durante la rampa
legend-largest-angle = angolo massimo di questa simulazione, ultimo periodo
legend-flutter-soft = inizio del flutter, dolce: cresce una piccola oscillazione
legend-flutter-hard = inizio del flutter, brusco: salto a una grande oscillazione
legend-divergence-onset = inizio della divergenza
legend-special-points = B: Bautin (da dolce a brusco), BT: Bogdanov-Takens, DH: doppio Hopf, ZH: zero-Hopf
legend-fold-of-cycles = piega dei cicli: sotto di essa nessuna oscillazione sopravvive
legend-hysteresis = isteresi: quiete e grande oscillazione entrambe stabili
describe-against = { $y } in funzione di { $x }
describe-range = { $state } da { $from } a { $to }
describe-ranges = intervalli: { $ranges }
describe-mark = { $name } a { $x }
describe-marked = segnati: { $marks }
describe-point = { $name } in ({ $x }, { $y })
describe-points = punti con nome: { $points }
describe-bands = colorata tra una piega dei cicli e un inizio brusco del flutter: la banda di isteresi, dove quiete e grande oscillazione sono entrambe stabili
describe-curves = { $count ->
    [one] { $count } curva
   *[other] { $count } curve
}
describe-now-stable = al carico attuale tutti i { $count } autovalori stanno a sinistra dell'asse immaginario: un colpetto si smorza
describe-now-flutter = al carico attuale { $right } di { $count } autovalori stanno a destra dell'asse immaginario, { $oscillating } fuori dall'asse reale: un'oscillazione cresce (flutter)
describe-now-divergence = al carico attuale { $right } di { $count } autovalori stanno a destra dell'asse immaginario, nessuno fuori dall'asse reale: la colonna si piega (divergenza)
describe-map = una mappa di { $columns } per { $rows } celle: stabile { $stable }%, flutter { $flutter }%, divergenza { $divergence }%

## The scene, the load bar and the tabs' own words

scene-name = la colonna
scene-swing = la sua oscillazione ora { $rad } rad
scene-hidden = la colonna, { $swing }
scene-analysing = la colonna, { $swing }; la sua stabilità è in analisi
scene-stable = stabile: un colpetto si smorza, fino a un centesimo in { $secs } s; { $swing }
scene-undamped = stabile ma non smorzata: un colpetto continua a oscillare, senza crescere né smorzarsi; { $swing }
scene-flutter = la colonna è in flutter: un'oscillazione cresce, raddoppiando ogni { $secs } s a { $frequency } rad/s; { $swing }
scene-divergence = divergenza: la colonna si piega lontano dalla retta, raddoppiando ogni { $secs } s; { $swing }
scene-stopped = la simulazione si è fermata: { $status }; R ne avvia una nuova
scene-drag-hint = trascina la punta o un giunto per spostare la colonna
scene-whole-reach = tutta la portata
    .tooltip = inquadra tutto il disco che la punta può raggiungere, fermo; spento, la vista segue il moto, allargandosi subito quando la colonna oscilla molto e stringendosi quando si calma, sempre con l'incastro in vista
scene-delta =
    .tooltip = δ: l'angolo dalla direzione dell'ultima asta (la freccia tratteggiata, dove punterebbe una forza follower ideale) alla forza che l'attrito del nastro applica davvero (la freccia piena), disegnato come l'arco in punta. δ = 0 è una follower perfetta; la rotella ruota la forza di δ mentre striscia di lato sul nastro (eq. 23)
scene-stick-slip = stick-slip: la velocità di strisciamento è sotto 1e-4 m/s; l'attrito di Coulomb è qui regolarizzato, fuori dalla validità del modello
scene-band = nastro che si muove a sinistra a V = { $speed } m/s
load-bar = carico{"\u000A"}p = { $load }
    .name = cursore del carico
    .tooltip = il carico p = P l/k: clicca o trascina qui, oppure usa le frecce (con la barra a fuoco: sinistra e destra, maiusc per dieci passi, home e fine)
load-bar-said = carico p = { $load } su 0 a { $end }
load-bar-said-hidden = { $load }: lo stato è nascosto finché la lezione non lo rivela
load-bar-said-analysing = { $load }: in analisi
load-bar-said-range = { $load }: { $state }, da p = { $from } a { $to }
load-bar-said-beyond = { $load }: oltre l'intervallo analizzato
view-hint = trascina: sposta · Ctrl+rotella: zoom · doppio clic: adatta
    .more = Mostra di nuovo tutti i dati (come un doppio clic su un grafico).{"\u000A"}Trascina o scorri per spostare, Ctrl+rotella per lo zoom, trascina un riquadro col tasto destro per ingrandirlo.
view-fit = adatta
map-readout-growth = tasso di crescita { $rate } 1/s
map-kick-settles = un colpetto si smorza
map-kick-hysteresis = un colpetto piccolo si smorza, uno grande lo lascia oscillare (isteresi)
map-kick-grows-softly = un colpetto cresce dolcemente fino a una piccola oscillazione
map-kick-jumps = un colpetto salta a una grande oscillazione
map-following = si seguono il confine del flutter e le pieghe dei cicli…
map-not-followed = confini non seguiti: { $why }
map-readout-hint = punta sulla mappa per leggere una cella; clicca per prenderne carico e parametro
histories-delta = δ: l'angolo della forza del nastro rispetto all'asta 2
histories-energy = energia cinetica + elastica
histories-band-power = potenza dal nastro
histories-rod-2 = asta 2
zoom-outside = lo zoom { $zoom } è fuori da { $least }-{ $most }: impostato a { $held } (Ctrl+0: 100%)
plot-name = grafico: { $y } in funzione di { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Calcolo del luogo delle radici di questi parametri...
locus-none = Nessun luogo delle radici per questi parametri.
locus-none-why = Nessun luogo delle radici per questi parametri: { $why }.
locus-title = luogo delle radici, p = da { $from } a { $to }
map-rows = righe { $done } di { $total }
map-grey-rows = le righe grigie non hanno analisi: { $why }
map-empty-range = l'intervallo della mappa da { $lo } a { $hi } è vuoto
map-no-thread = nessun thread per la mappa: { $why }
map-stopped = la mappa si è fermata: { $why }
map-axis = carico p rispetto a
    .tooltip = il secondo parametro della mappa (il suo intervallo qui sotto riavvia la mappa)
map-from = da
    .name = intervallo della mappa da
    .tooltip = dove inizia il secondo parametro
map-to = a
    .name = intervallo della mappa a
    .tooltip = dove finisce il secondo parametro
paradox-computing = calcolo dei carichi di flutter mentre lo smorzamento svanisce ...
paradox-joints = Il carico di flutter con smorzatori nei giunti c1 = (c1/c2) c2 quando il livello di smorzamento g2 = c2 / sqrt(k m l^2) tende a zero: il limite dipende dal rapporto e sta sotto il carico non smorzato (paradosso di Ziegler).
paradox-external = Il carico di flutter con smorzatori uguali nei giunti c1 = c2 = c (smorzamento interno) e resistenza c_ext = (c_ext l^3 / c) c / l^3 lungo le aste (smorzamento esterno) quando il livello g2 = c / sqrt(k m l^2) tende a zero: anche lo smorzamento esterno destabilizza, e il limite dipende dal rapporto.
paradox-no-extent = le curve non hanno estensione lungo il rapporto
paradox-no-thread = nessun thread per le curve: { $why }
paradox-dead-load = Un carico fisso (eta = 0) è conservativo: non va mai in flutter, quindi non c'è paradosso da mostrare.
paradox-stable-throughout = Nessuna curva da tracciare: a ogni rapporto mostrato la colonna resta stabile fino a p = { $end }.
paradox-failed = Nessuna curva da tracciare: { $why }.
paradox-kind = smorzamento che svanisce:
paradox-kind-joints = smorzatori nei giunti
    .tooltip = gli smorzatori nei giunti c1 e c2 nel rapporto c1/c2
paradox-kind-external = resistenza esterna e interno
    .tooltip = resistenza c_ext lungo le aste (esterna) e smorzatori uguali nei giunti c1 = c2 = c (interno) nel rapporto c_ext l^3 / c
paradox-roller = Il carico a cui la colonna con rotella perde per prima la stabilità, in funzione della massa della rotella, per tre velocità del nastro (lo smorzamento da strisciamento è mu R / V).
paradox-roller-falling = in calo verso zero per nu -> 0
paradox-roller-flat = non in calo verso zero in questo intervallo
paradox-roller-massless = ; la rotella senza massa (la follower ideale) perde la stabilità a p = { $load }
paradox-roller-caption = { $intro } Alla massa più piccola mostrata, nu = { $nu }, le curve stanno a { $at }, { $trend }{ $massless }.
record-next = i prossimi
record-secs = s in
    .name = secondi da registrare
    .tooltip = secondi della finestra da registrare (da 1 a 60)
record-folder =
    .name = cartella della registrazione
    .tooltip = la cartella in cui va la GIF
record-choosing = scelta in corso...
record-choose = scegli...
    .tooltip = scegli la cartella nella finestra di dialogo del desktop
    .title = zieglerlab: la cartella delle registrazioni
record-start = registra
    .tooltip = registra ciò che mostra la finestra, 10 fotogrammi al secondo, in una GIF
    .no-folder = la cartella non esiste

## A lesson's revealed results

reveal-never = la colonna non perde stabilità fino a p = { $load }
reveal-theory = la teoria: instabile da p = { $load }
reveal-seen = ; il moto si è visto a p = { $load }
reveal-predicted = Hai previsto p = { $load };{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Giusto: hai scelto «{ $chosen }», la risposta.
reveal-wrong = Non questa: hai scelto «{ $chosen }»; la risposta è «{ $answer }».
reveal-answer = La risposta: «{ $answer }».
reveal-no-answer = la teoria non ha risposta a questo carico
reveal-period = , un periodo di { $secs } s
reveal-flutter = flutter: l'oscillazione raddoppia ogni { $secs } s{ $period }
reveal-divergence = divergenza: l'inclinazione raddoppia ogni { $secs } s
reveal-stable = stabile: un colpetto si dimezza ogni { $secs } s{ $period }
reveal-undamped = stabile: un colpetto né cresce né si smorza{ $period }
reveal-here = La teoria a p = { $load }: { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = aste = { $rods }: la barra del carico ora va da 0 a { $end }, e il carico si è spostato con essa da p = { $from } a { $to } (lo stesso punto della barra; scrivi il carico per impostarne un altro)
notice-rods-load-kept = aste = { $rods }: il carico p = { $load } resta ({ $why })
notice-switched-to-reference = la colonna è troppo rigida per l'integratore rapier con il suo passo di 1/240 s (smorzamento o rigidezza enormi rispetto a poca massa); passato all'integratore di riferimento
notice-lesson-last-step = questo era l'ultimo passo della lezione: chiudila, o aprine un'altra dal menu lezioni
notice-paste-nothing = niente da incollare: copia prima il testo delle impostazioni («copia impostazioni» nel menu condividi), o scrivilo nella casella
notice-paste-not-understood = impostazioni incollate rifiutate, nulla è cambiato: { $what } non compreso
notice-pasted = impostazioni incollate
notice-not-saved = non salvato: nessun file scelto (dove non si è aperta una finestra di dialogo, questo desktop non ne offre)
recording-saved = registrazione salvata in { $path }: { $frames } fotogrammi in { $secs } s{ $slow }
recording-jerky = ; ha catturato solo { $caught } fotogrammi al secondo dei { $fps } al secondo di cui è fatta la GIF (la frequenza di cattura: la macchina era troppo occupata per prenderne di più), quindi la GIF va alla giusta velocità ma a scatti: una finestra più piccola (o la modalità proiettore spenta) ne registra di più
recording-title = { $title }: registrazione, mancano { $secs } s
recording-making = creazione della GIF: fotogramma { $done } di { $kept }
save-as = salva come
    .path = percorso per salvare
save-as-typed = Su questo desktop non si è aperta alcuna finestra di dialogo: scrivi dove salvare { $what }.
save-as-exists = { $path } esiste già: sostituirlo? (salva di nuovo per sostituire)
save-as-replace = sostituisci
save-as-save = salva
save-as-cancel = annulla
save-as-what-table = la tabella (CSV)
save-as-what-plots = i grafici (PNG)
save-as-no-path = digitare il percorso di un file
save-as-no-folder = la sua cartella non esiste
save-as-folder = è una cartella: digitare il nome di un file al suo interno
save-as-pipe = è una pipe o un dispositivo, non un file: digitare il percorso di un file
save-as-protected = il file esiste e non può essere scritto ({ $why }); resta com'è

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (esterno / interno)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = smorzamento g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds }: una curva, il primo carico critico non dipende da V
paradox-reference-undamped = non smorzata
paradox-reference-massless = nu = 0: la follower ideale
paradox-reference = { $name }: p = { $load }
paradox-reference-above = { $name }: p = { $load } (sopra l'asse)

## Refused values and the engine's failures

refused-value = { $subject } = { $value }: { $allowed }
refused-not-a-number = '{ $text }' non è un numero
refused-unknown-preset = preimpostazione sconosciuta '{ $name }'; le preimpostazioni sono: { $known }
refused-unknown-key = chiave sconosciuta '{ $key }'; le chiavi sono: { $known }
refused-malformed = '{ $text }' non è chiave=valore con un numero (per es. load=2.5): { $reason }
refused-conflict = { $first } e { $second } impostano la stessa grandezza; indicarne una sola
allowed-finite = deve essere un numero finito
allowed-positive = deve essere > 0
allowed-non-negative = deve essere >= 0
allowed-key-range = deve essere un numero finito { $range } { $unit }
allowed-key-count = deve essere un numero intero { $range }
allowed-between = deve essere compreso tra { $min } e { $key } = { $max }
allowed-rods = deve essere un numero intero da 2 a { $most }
allowed-eta-range = deve essere compreso tra 0 (carico fisso) e 1 (forza follower)
allowed-frictionless-band = deve essere > 0: senza attrito il nastro non esercita alcun carico (per una colonna scarica impostare il carico a 0)
allowed-friction-too-small = troppo piccolo: il carico p = { $load } richiederebbe una forza normale R = P / mu oltre ogni numero
allowed-beyond-analysis = oltre ciò che l'analisi può elevare al quadrato (grandezze da { $smallest } a { $largest })
allowed-makes-beyond-analysis = porta { $what } oltre ciò che l'analisi può elevare al quadrato (grandezze da { $smallest } a { $largest })
allowed-masses-too-unequal = le masse sono troppo diverse: il determinante della matrice delle masse è sotto 1e-12 della sua scala, quindi l'arrotondamento decide il moto (per es. una massa in punta o una rotella oltre circa 1e12 volte quella delle aste)
allowed-mass-missing = la colonna ha bisogno di massa oltre il giunto A (asta 2, punta o rotella) e di massa o inerzia che si muova con la sola asta 1; la matrice delle masse è singolare
allowed-chain-massless = una catena ha bisogno di massa o inerzia su ogni copia dell'asta 2 (m2 o I2 > 0): con l'asta 2 priva di massa la matrice delle masse della catena è singolare
allowed-needs-damped-joint2 = richiede un giunto 2 smorzato: impostare prima c2 > 0 (o il livello di smorzamento)
allowed-infinite-damper-ratio = c2 = 0 con c1 > 0: il rapporto c1/c2 da mantenere è infinito; impostare prima c2 > 0
allowed-band-at-rest = deve essere > 0 per l'analisi lineare: a V = 0 l'attrito coulombiano non è derivabile attorno alla quiete (stick-slip)
allowed-roller-has-no-eta = la rotella non ha eta: l'attrito del nastro dà la direzione della forza, opposta allo strisciamento al contatto, e il suo angolo delta dall'asta 2 è un risultato del moto, non un parametro
allowed-state-length = deve essere 2 (aste + 1): gli angoli, la rotazione e le loro velocità
allowed-time-step = deve essere un passo temporale in (0, 1] s
quantity-load-force = il carico P
quantity-load-p = il carico p = P l/k
quantity-inertia-o = l'inerzia attorno a O
quantity-inertia-coupling = l'inerzia di accoppiamento
quantity-inertia-a = l'inerzia attorno ad A
quantity-stiffness-k1 = la rigidezza k1
quantity-stiffness-k2 = la rigidezza k2
quantity-damper-c1 = lo smorzatore c1
quantity-damper-c2 = lo smorzatore c2
quantity-drag = la resistenza c_ext l^3
quantity-slip-damping = lo smorzamento di strisciamento mu R l^2 / V
quantity-spin-inertia = l'inerzia di rotazione della rotella m3 r^2 / 2
quantity-mass-matrix = la matrice delle masse
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = la lunghezza dello stato
quantity-time-step = dt
engine-too-stiff = il motore rapier non può integrare questa colonna con dt = { $step } s: le sue molle e i suoi smorzatori raggiungono velocità di { $rate } 1/s, che richiedono dt < { $need } s; usare il motore di riferimento
engine-rapier-world = non è stato possibile costruire il mondo rapier2d per questa colonna (i suoi giunti sono stati rifiutati); usare il motore di riferimento
analysis-not-converged = l'iterazione degli autovalori non è andata a convergenza al carico p = { $load }
ramp-refused-end = { $end } = { $value }: deve essere un carico p >= 0
ramp-refused-rate = velocità della rampa = { $value }: deve essere un carico positivo al secondo
ramp-refused-too-slow = velocità della rampa = { $value }: deve essere almeno { $slowest } di carico al secondo (più lento, il carico non si muoverebbe visibilmente per giorni)
ramp-refused-too-long = la rampa da { $from } a { $to } a { $rate } al secondo richiede { $secs } s di tempo simulato; al massimo { $most } s (circa quattro mesi): una velocità maggiore o estremi più vicini
ramp-refused-model = { $end } = { $value }: { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = rampa: { $why }
notice-ramp-stopped = rampa fermata: { $why }
notice-map-point-refused = mappa: { $why }
notice-overlay-unavailable = sovrapposizione non disponibile: { $why }
notice-table-not-saved = non salvato: { $why }
notice-no-locus = non c'è luogo delle radici per questi parametri
notice-no-thread = non salvato: nessun thread per scrivere ({ $why })
notice-saved-lines = salvate { $count ->
    [one] { $count } riga
   *[other] { $count } righe
} in { $path }
notice-write-failed = non salvato: { $why }
notice-plots-saved = grafici salvati in { $path }
notice-plots-not-saved = grafici non salvati: { $why }
notice-recording-failed = registrazione non riuscita: { $why }
notice-layout-not-saved = disposizione della finestra non salvata: { $why }
notice-stored-overlay = la sovrapposizione salvata { $name } non è una preimpostazione; nessuna sovrapposizione
notice-stored-map-axis = l'asse della mappa salvato non è usato: { $why }
notice-stored-language = la lingua salvata non è usata: { $why }
notice-lesson-refused = lezione { $name }: { $why }
notice-lesson-not-opened = lezione non aperta: { $why }
notice-reset-closed-lesson = tutto azzerato: la lezione "{ $title }" è chiusa (riaprirla dal menu delle lezioni)

## The post-critical tab's notes

cycles-computing = si seguono i cicli limite da ogni inizio del flutter ...
cycles-none = nessun ciclo limite: { $why }
cycles-no-onset = nessun inizio del flutter nell'intervallo della barra del carico: nessun ciclo limite
cycles-chain-too-long = una catena di { $rods } aste richiede troppo tempo per essere seguita nella finestra (16 aste richiedono circa 20 s su due core, e il lavoro cresce più in fretta del numero di aste); `zieglerlab bifurcation` ne calcola i cicli dalla riga di comando
cycles-no-thread = nessun thread per i cicli: { $why }
cycles-branch = { $name }: insorgenza { $onset } a p = { $at }; il ramo è terminato: { $end }
cycles-offshoot = { $name }: cicli asimmetrici (e le loro immagini speculari) dal BPC a p = { $at }; il ramo è terminato: { $end }
cycles-onset-soft = dolce
cycles-onset-hard = brusca
cycles-no-branch = inizio del flutter a p = { $at }: { $why }
cycles-no-branch-reversible = nessuno smorzamento, una colonna reversibile: nessun ciclo limite da seguire
cycles-no-branch-degenerate = il primo coefficiente di Ljapunov è nullo entro la sua accuratezza; cicli non seguiti
cycles-no-branch-not-converged = il metodo di shooting non è andato a convergenza vicino all'insorgenza; nessun ciclo
cycles-end-left-range = è uscito dall'intervallo dei carichi
cycles-end-large-amplitude = l'ampiezza di un angolo ha superato { $most } rad (la colonna compie un giro)
cycles-end-long-period = il periodo è cresciuto oltre { $most } volte quello dell'insorgenza
cycles-end-lost = il metodo di shooting non è andato a convergenza oltre p = { $load }
cycles-end-stick-slip = il contatto della rotella si avvicina all'aderenza sul nastro oltre p = { $load } (stick-slip: lì l'attrito non è liscio)
cycles-end-unresolved = i cicli oltre p = { $load } non sono risolti (moltiplicatore banale lontano da 1 più di { $tolerance })
cycles-end-point-limit = { $most } cicli calcolati
cycles-end-cancelled = fermato su richiesta

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = la stabilità non è risolta: a p = { $load } i modi vanno da { $fastest } 1/s a { $slowest } 1/s, un rapporto oltre { $span }, quindi i tassi di crescita dei modi lenti sono lasciati all'arrotondamento (un modo molto più veloce degli altri, come la rotazione di una rotella di massa nu minima)
not-resolved-slow-mode-lost = la stabilità non è risolta: a p = { $load } i modi vanno da { $scale } 1/s a { $slowest } 1/s, quindi i tassi di crescita sotto { $tolerance } 1/s si perdono nell'arrotondamento (il modello è vicino a un limite singolare: un nastro V molto lento o uno smorzamento molto grande)
not-resolved-methods-disagree = la stabilità non è risolta: a p = { $load } le radici seguite e la decomposizione di Schur non concordano sullo stato (lo decide l'arrotondamento: un modo molto più veloce degli altri, come la rotazione di una rotella di massa nu minima); i carichi critici mostrati possono essere spuri o mancare
not-resolved-rounding-decides = la stabilità non è risolta: per p da { $low } a { $high } i tassi di crescita stanno tra 1e-12 e 1e-10 della scala delle frequenze, dove l'arrotondamento decide lo stato (una rotella di massa nu minima, il cui debole flutter cresce in proporzione a nu, o un nastro V molto lento); i carichi critici mostrati possono essere spostati o mancare
not-resolved-refinement-cut = il luogo delle radici è stato raffinato solo fino a p = { $load }: oltre, i rami sono campionati solo ai carichi equispaziati, quindi può mancare una finestra di un altro stato più stretta della loro spaziatura (è stato raggiunto il limite di tempo e memoria del raffinamento)

## The stored state's check before the window opens (a damaged store)

store-zoom = il fattore di zoom { $zoom } (ammesso da 0.2 a 5)
store-geometry = la geometria della finestra { $width } x { $height } punti in scala { $scale }
store-unreadable = non è stato possibile leggere lo stato salvato ({ $why }); una copia è conservata in { $copy }; si parte dai valori predefiniti
store-unreadable-uncopied = non è stato possibile leggerlo ({ $why }) né copiarlo ({ $error })
store-moved = lo stato salvato { $path } { $why }; viene spostato in { $aside } e si usano i valori predefiniti
store-not-moved = lo stato salvato { $path } { $why } e non è stato possibile spostarlo ({ $error }); le impostazioni non saranno salvate
store-folder-not-made = le impostazioni non saranno salvate: non è possibile creare la cartella { $folder } ({ $error })
store-folder-full = le impostazioni non saranno salvate: la cartella { $folder } non accetta nuovi file ({ $error })
store-not-writable = le impostazioni non saranno salvate: non è possibile scrivere { $path } ({ $error })
store-is-folder = è una cartella
store-is-device = è un dispositivo, una pipe o un socket
store-too-large = contiene { $bytes } byte (se ne leggono al massimo { $most })
store-entry = { $why } (voce '{ $key }' di eframe)
store-ignored = stato salvato: ignorato { $what }
store-ignored-not-rewritten = stato salvato: ignorato { $what } (non è stato possibile riscrivere il file: { $error })
store-settings-unreadable = non è stato possibile leggere le impostazioni salvate
store-original-kept = l'originale è conservato in { $copy }
store-original-lost = non è stato possibile conservare una copia dell'originale ({ $error })
store-settings-partly = impostazioni salvate: ignorato { $what }; il resto è mantenuto
store-settings-ignored = impostazioni salvate ignorate ({ $why }); si parte dai valori predefiniti
layout-ignored = disposizione della finestra salvata ignorata ({ $why }); si usa la disposizione predefinita
notice-paste-unreadable = impostazioni incollate non comprese, nulla è cambiato: { $why }
notice-paste-refused = impostazioni incollate rifiutate, nulla è cambiato: { $why }
notice-analysis-unavailable = analisi non disponibile: { $why }
notice-lesson-step = passo { $step } della lezione: { $why }
notice-lesson = lezione: { $why }
