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
