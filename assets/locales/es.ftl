### zieglerlab: los textos de la ventana en español.
###
### Los mismos mensajes que en.ftl, con los mismos marcadores; los números
### llegan ya escritos, con punto decimal como en la línea de órdenes.
###
### Glosario (igual en todas partes):
###   flutter: flameo (inestabilidad dinámica)   divergence: divergencia
###   follower force: fuerza seguidora           dead load: carga muerta
###   critical load: carga crítica               root locus: lugar de las raíces
###   eigenvalue: autovalor                      growth rate: tasa de crecimiento
###   damping: amortiguamiento                   limit cycle: ciclo límite
###   Hopf bifurcation: bifurcación de Hopf (inicio suave / brusco)
###   rod: barra     column: columna             spring: resorte de torsión
###   roller: rodillo  moving band: banda móvil  friction: rozamiento
###   stability map: mapa de estabilidad         Ziegler's paradox: paradoja de Ziegler

## Counts

rods-count = { $count ->
    [one] { $count } barra
   *[other] { $count } barras
}

## The sidebar's heading and its menus

menu-share = compartir
    .tooltip = los ajustes como texto: copiarlos o pegar otros
menu-record = grabar
    .tooltip = grabar la ventana en un GIF
menu-keys = teclas
    .tooltip = las órdenes del teclado
menu-language = el idioma de la ventana (se recuerda en el próximo inicio)
    .name = idioma: { $language }
projector-toggle = proyector (P)
overlay = comparar
    .none = ninguno
    .tooltip = el lugar de las raíces de otro modelo en gris, con el mismo a (como la Fig. 8 pone la columna ideal junto al rodillo)
section-parameters = parámetros

## The status line at the window's foot

status-dismiss = cerrar
    .tooltip = borrar este mensaje
status-latest = el último mensaje (el texto completo)
status-got-it = entendido
    .tooltip = ocultar la sugerencia
status-ready = listo
hint-first-launch = Arrastra la barra de carga hasta 3 más o menos y pulsa K para dar un golpe a la columna (la barra espaciadora pausa).

## The tabs

tab-locus = lugar de las raíces
    .tooltip = el lugar de las raíces: los autovalores de la columna en el plano complejo y frente a la carga. A la izquierda del eje vertical un movimiento se amortigua, a la derecha crece; la altura es la frecuencia. El flameo empieza donde un par cruza el eje
tab-histories = historias temporales
    .tooltip = los ángulos, la energía y la potencia de la banda durante la simulación
tab-map = mapa de estabilidad
    .tooltip = la estabilidad de cada carga frente a un segundo parámetro
tab-paradox = paradoja
    .tooltip = la primera carga crítica cuando el amortiguamiento (o la masa del rodillo) tiende a cero
tab-post-critical = poscrítico
    .tooltip = pasado el inicio del flameo: el tamaño de los ciclos límite frente a la carga, estables o no, y la oscilación de la propia columna en marcha
save-png = guardar PNG...
    .tooltip = estos gráficos como imagen, sin botones ni sugerencias
save-csv = guardar CSV...
    .tooltip = los números de estos gráficos, en las columnas de la línea de órdenes, en un archivo
answer-hidden = Este gráfico muestra la respuesta: vuelve cuando la lección la revela.
answer-hidden-histories = { answer-hidden } Las historias temporales muestran qué hace la columna.
tab-in-column-place = La pestaña «{ $tab }» está en el lugar de la columna; la pestaña lugar de las raíces devuelve la columna.
locus-beside-column = El lugar de las raíces está junto a la columna; una pestaña elegida aquí aparece en el lugar de la columna.
plots-need-room = Los gráficos necesitan aquí más espacio: una ventana más alta, o el modo proyector apagado (P).

## The welcome of a first launch

welcome-title = Bienvenido a zieglerlab
welcome-column = Dos barras sobre resortes están empotradas por un extremo. En el otro extremo una fuerza empuja a lo largo de la última barra y gira con ella: una fuerza seguidora. Aquí se produce como en el laboratorio, con un rodillo que arrastra una banda móvil.
welcome-states = Con cargas pequeñas, un golpe produce una oscilación que sigue siendo pequeña: la columna es estable. Pasada una carga crítica entra en flameo: oscila de un lado a otro, cada vez más. Con cargas aún mayores puede divergir: se dobla hacia un lado sin oscilar.
welcome-locus = El lugar de las raíces muestra con números (sus autovalores) cómo se mueve la columna mientras la carga crece. A la izquierda del eje vertical una oscilación se amortigua; a la derecha, crece. Cuánto a la derecha es la tasa de crecimiento; cuánto arriba, la frecuencia.
welcome-try = Arrastra la barra de carga y observa ambos: la columna empieza el flameo con la carga a la que los autovalores cruzan el eje.
welcome-first-lesson = empezar la primera lección
    .tooltip = unos pocos pasos: predice dónde empieza el flameo y luego observa
welcome-explore = explorar por mi cuenta
    .tooltip = cerrar esto; las lecciones siguen arriba en la barra lateral

## States and critical loads

state-stable = estable
state-flutter = flameo
state-divergence = divergencia
transition = p = { $load }: { $from } -> { $to }
transition-meaning = p = { $load }: la columna pasa de { $from } a { $to }; { $how }
    .to-flutter = por encima de esta carga un par de autovalores queda a la derecha del eje imaginario: un golpe se convierte en una oscilación cada vez mayor
    .to-divergence = por encima de esta carga un autovalor real es positivo: la columna se inclina sin oscilar
    .to-stable = por encima de esta carga ningún autovalor queda a la derecha del eje imaginario: un golpe ya no crece
duration-forever = nunca
duration-days = { $count ->
    [one] { $n } día
   *[other] { $n } días
}
duration-years = { $count ->
    [one] { $n } año
   *[other] { $n } años
}

## The model and the engine

model = modelo
    .source = { $source }: dónde está el modelo en el estudio que sigue este programa (su figura y ecuaciones)
preset-ziegler-1952 = Ziegler 1952
    .description = La columna de Ziegler: barras sin masa, masa puntual 2m en la articulación A y m en el extremo, fuerza seguidora ideal
preset-uniform-rods = Fig. 1a
    .description = Barras rígidas homogéneas de masa m (Fig. 1a), fuerza seguidora ideal
preset-midpoint-masses = Fig. 1b, ec. 1-7
    .description = Barras sin masa con una masa puntual m en el centro de cada una (Fig. 1b, ec. 1-7), fuerza seguidora ideal
preset-roller = Fig. 7, ec. 8-38
    .description = Barras homogéneas con un rodillo arrastrado por una banda móvil (Fig. 7, ec. 8-38), inercia de giro coherente; parámetros de la Fig. 8
preset-roller-as-printed = ec. 39, Fig. 8
    .description = El modelo del rodillo tal como se imprimió en la ec. (39): la inercia de giro multiplicada por r/l2, una errata del artículo; parámetros de la Fig. 8
preset-tabletop = ritmo de clase
    .description = Una columna de mesa para una clase: barras homogéneas de 25 cm y 100 g, resortes de 0.0625 N m/rad (a = 10 1/s^2), fuerza seguidora ideal; pasado p = 2.54 entra en flameo con un periodo de unos 1.5 s
preset-tabletop-roller = ritmo de clase
    .description = La columna de mesa empujada por un rodillo de 10 g y 2.5 cm de radio sobre una banda a 0.1 m/s (nu = rho = mu = 0.1): un flameo débil desde p = 0.024 que tarda minutos en crecer, y uno fuerte cerca de la carga de la columna ideal
preset-beck = Beck 1952, una cadena de 16 barras
    .description = La columna de Beck como cadena de 16 barras homogéneas con resortes k en cada articulación (una viga con EI = k l, L = 16 l), fuerza seguidora: flameo en P L^2/EI = 18.78 (columna continua de Beck: 20.05)
preset-pflueger = La columna de Pflüger, una cadena de 16 barras
    .description = La columna de Pflüger: la cadena de Beck de 16 barras con una masa en el extremo igual a la mitad de la masa de la columna, fuerza seguidora: la masa del extremo baja la carga de flameo a P L^2/EI = 15.06
preset-beck-roller = La cadena de Beck cargada como en Bigoni et al. 2018
    .description = La cadena de Beck de 16 barras cargada por el rodillo sobre la banda móvil (los grupos del artículo en cada barra: masa del rodillo 0.1 m, radio 0.1 l, mu = 0.1, V = 0.1 m/s): el amortiguamiento del deslizamiento la hace entrar en flameo débil desde P L^2/EI = 0.025 (crecimiento por debajo de 3e-4 1/s), y fuerte desde unos 18.8, donde entra en flameo la cadena con fuerza seguidora
preset-pflueger-roller = La cadena de Pflüger cargada como en Bigoni et al. 2018
    .description = La cadena de Pflüger de 16 barras (masa del extremo la mitad de la de las barras) cargada por el mismo rodillo sobre la banda móvil: flameo débil desde P L^2/EI = 0.008 (crecimiento por debajo de 4e-5 1/s), flameo fuerte desde 15.06, donde entra en flameo la cadena con fuerza seguidora
tip-force-dead = fuerza en el extremo: una carga muerta (eta = 0), de dirección fija, en lugar de la fuerza seguidora del modelo
tip-force-partial = fuerza en el extremo: en parte tangencial, girada eta = { $eta } veces el ángulo de la última barra (la fuerza seguidora del modelo tiene eta = 1)
engine = integrador
    .tooltip = qué integra el movimiento: la simulación sigue desde donde está
engine-rapier = rapier
    .tooltip = rapier: el motor físico rapier2d, barras como sólidos rígidos unidos por bisagras (un sistema multicuerpo), el giro del rodillo implícito
engine-reference = referencia
    .tooltip = Dormand-Prince 5(4) adaptativo sobre las ecuaciones exactas

## The load

load-field = carga p = P l/k
    .tooltip = escribe una carga (Intro aplica, Escape restaura); también más allá del final de la barra
    .meaning = la carga sin unidades: la fuerza P del extremo por la longitud de la barra l entre la rigidez de los resortes k (la columna de Ziegler entra en flameo desde p = 2.09)
roller-load = rodillo: q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = la carga propia del rodillo: la fuerza R que lo aprieta contra la banda, en las unidades de p; el rozamiento de la banda empuja con μ R, así que p = μ q
notes-more = ... y { $count } más (pasa el ratón)
load-beyond-range = p = { $load } está fuera del intervalo dibujado (de 0 a { $end }); el estado de abajo es en p
critical-loads-hidden = Las cargas críticas están ocultas hasta que la lección las revele.
not-resolved = la estabilidad no está resuelta aquí (pasa el ratón para ver por qué)
ramp-visible = el extremo desplazado un { $percent }% de la longitud
ramp-theory = teoría (marca blanca): inestable desde p = { $load }
ramp-seen = visto (marca): movimiento visible en p = { $load } ({ $visible })
ramp-seen-late = visto (marca): movimiento visible en p = { $load }, con retraso: pasa el ratón para ver por qué ({ $visible })
    .why = Aparece con retraso: pasado el inicio, el movimiento necesita tiempo para crecer hasta un tamaño visible, y entretanto la rampa sigue avanzando. Una rampa más lenta lo muestra más cerca de la teoría.
ramp-watching = esperando a que el movimiento sea visible ({ $visible })

## The parameters

groups = grupos adimensionales
    .tooltip = las pocas combinaciones de los valores SI que deciden el movimiento (a = k/(m l^2) fija su rapidez; nu, rho, mu y V del rodillo su masa, tamaño, rozamiento y la velocidad de la banda); cambiar uno mantiene los demás
si-parameters = parámetros SI
mu-moves-load = (R fijo: mueve p)
key-allowed = { $description } (permitido: { $range })
refused = rechazado: { $why }
key-load = carga p = P l/k en el eje común (P = mu R para el rodillo; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2): fija k1 (y k2 en la misma proporción), mantiene p
    .range = > 0
key-nu = nu = m3/m, masa del rodillo entre la masa de la barra
    .range = >= 0
key-rho = rho = r/l, radio del rodillo entre la longitud de la barra
    .range = en (0, l2/l]
key-mu = coeficiente de rozamiento; en las ecuaciones solo entra mu R, así que R se mantiene y la carga p = mu R l/k cambia
    .range = > 0
key-V = velocidad de la banda (se mueve hacia -x); el análisis lineal necesita V > 0
    .range = >= 0
key-l1 = longitud de la barra 1 (su distribución de masa escala con ella)
    .range = > 0
key-l2 = longitud de la barra 2 (su distribución de masa escala con ella)
    .range = > 0
key-m1 = masa de la barra 1, incluidas sus masas puntuales (se mantiene la distribución)
    .range = >= 0
key-m2 = masa de la barra 2 (se mantiene la distribución)
    .range = >= 0
key-s1 = centro de masa de la barra 1, desde el empotramiento O
    .range = en [0, l1]
key-s2 = centro de masa de la barra 2, desde la articulación A
    .range = en [0, l2]
key-I1 = momento de inercia de la barra 1 respecto a su centro de masa
    .range = >= 0
key-I2 = momento de inercia de la barra 2 respecto a su centro de masa
    .range = >= 0
key-m_tip = masa puntual en el extremo B (la masa del rodillo es m3)
    .range = >= 0
key-k1 = resorte de torsión en el empotramiento O
    .range = > 0
key-k2 = resorte de torsión en la articulación A
    .range = > 0
key-c1 = amortiguador viscoso en el empotramiento O
    .range = >= 0
key-c2 = amortiguador viscoso en la articulación A
    .range = >= 0
key-c_ext = resistencia viscosa externa a lo largo de ambas barras (resistencia del aire, linealizada): una fuerza por unidad de longitud igual a c_ext por la velocidad local transversal a la barra
    .range = >= 0
key-rods = barras de la cadena: la barra 1 y luego copias de la barra 2 con el resorte y el amortiguador de la articulación A en cada articulación; la masa del extremo y la carga al final de la última barra
    .range = de 2 a 64
key-P = módulo de la fuerza en el extremo
    .range = >= 0
key-eta = tangencialidad de la fuerza en el extremo: su dirección gira eta veces el ángulo de la última barra (1: fuerza seguidora, 0: carga muerta)
    .range = en [0, 1]
key-m3 = masa del rodillo (0: sin masa, la fuerza seguidora ideal)
    .range = >= 0
key-r = radio del rodillo
    .range = en (0, l2]
key-R = fuerza normal del rodillo sobre la banda
    .range = >= 0

## Time

command-play = iniciar
    .running = pausa
    .tooltip = iniciar / pausa
command-load-up = subir carga
    .tooltip = sube la carga una centésima de la barra
command-load-down = bajar carga
    .tooltip = baja la carga una centésima de la barra
command-kick = golpe
    .tooltip = golpe: cada barra girada 0.03 rad
command-reset = reiniciar
    .tooltip = reiniciar: una nueva simulación desde la perturbación estándar
command-reset-all = reiniciar todo
    .tooltip = reiniciar todo: los parámetros y la carga del modelo, velocidad normal, una nueva simulación, las vistas por defecto; una lección abierta se cierra
command-projector = modo proyector
    .tooltip = modo proyector: alto contraste, texto grande
command-next = siguiente
    .tooltip = el paso siguiente de la lección (el mando de un presentador envía Av Pág)
command-back = atrás
    .tooltip = el paso anterior de la lección (Re Pág)
command-full-screen = pantalla completa
    .tooltip = pantalla completa: la ventana llena la pantalla (otra vez para salir)
command-step = paso
    .tooltip = un paso del integrador (1/240 s), luego pausa
key-space = espacio
key-right = derecha
key-up = arriba
key-left = izquierda
key-down = abajo
key-page-down = Av Pág
key-page-up = Re Pág
focus-keys-tab = el control siguiente (mayús+tab: el anterior)
    .keys = tab
focus-keys-ctrl-tab = la pestaña siguiente (ctrl+mayús+tab: la anterior)
    .keys = ctrl+tab
focus-keys-press = con un botón, casilla, selector o pestaña enfocado: pulsarlo (el espacio solo inicia si no hay nada enfocado)
    .keys = espacio, intro
focus-keys-slider = con un deslizador enfocado (la barra de carga, la predicción): moverlo una centésima; mayús: una décima
    .keys = izquierda, derecha
focus-keys-column = con la columna enfocada (tab hasta ella): girarla 0.02 rad en un sentido u otro, mayús: 0.1 rad (el arrastre por teclado)
    .keys = izquierda, derecha
focus-keys-ends = con la barra de carga o la predicción enfocada: sus extremos
    .keys = inicio, fin
focus-keys-plot = con un gráfico enfocado (tab hasta él): desplazar una décima, ampliar en torno al centro; intro: un mapa toma la celda bajo la cruz
    .keys = flechas, +, -
focus-keys-escape = soltar el foco (un campo de texto: deshacer lo escrito)
    .keys = esc
focus-keys-others = Av Pág, Re Pág, K, R, P y arriba/abajo funcionan tenga el foco lo que tenga, salvo un campo de texto en edición
    .keys = los demás
pace-slow = Lento
    .tooltip = un cuarto del tiempo real
pace-normal = Normal
    .tooltip = tiempo real: un segundo simulado por segundo
pace-fast = Rápido
    .tooltip = cuatro veces el tiempo real
speed-factor = × velocidad
    .tooltip = segundos simulados por segundo de reloj
run-time = t = { $secs } s   ({ $status })
run-paused = en pausa
run-running = en marcha
run-diverged = divergió en t = { $secs } s
run-too-stiff = demasiado rígida para el integrador de referencia en t = { $secs } s: un rodillo muy ligero o una banda parada (el integrador rapier los maneja), o una carga o rigidez tan grandes que ningún paso resuelve las velocidades de la columna
run-too-fast = demasiado rápida para el integrador rapier en t = { $secs } s: la columna gira a { $rate } rad/s, más de lo que resuelve su paso fijo ({ $most } rad por paso); el integrador de referencia la sigue
run-lagging = en marcha a { $achieved }x: este ordenador no llega a { $asked }x

## The status card

card-stable =
    .meaning = estable: un pequeño golpe sigue siendo pequeño (se amortigua o, sin ningún amortiguamiento, conserva su tamaño)
card-flutter =
    .meaning = flameo: la columna oscila de un lado a otro, cada vez más (un par de autovalores a la derecha del eje)
card-divergence =
    .meaning = divergencia: la columna se dobla hacia un lado sin oscilar (un autovalor real a la derecha del eje)
card-weak-flutter = flameo débil
    .meaning = flameo débil: la oscilación crece, pero menos del 1% de su frecuencia: despacio, a lo largo de muchas oscilaciones
card-hidden = ¿estable o no?
    .why = El veredicto está oculto hasta que la lección lo revele: observa la columna.
card-no-figures = sin datos de estabilidad: { $why }
card-growth = tasa de crecimiento  { $rate } 1/s
    .tooltip = tasa de crecimiento: lo rápido que el movimiento crece (positiva) o se amortigua (negativa), por segundo: la parte real del autovalor más a la derecha
card-growth-zero = tasa de crecimiento  0 (dentro de { $tolerance } 1/s)
card-not-resolved = no resuelto con estos parámetros: mira el aviso bajo la carga
card-e-folding = tiempo de crecimiento e  { $time }
    .tooltip = tiempo de crecimiento e: el tiempo en que la oscilación crece un factor e = 2.72 (1 / tasa de crecimiento)
card-decay = tiempo de amortiguamiento  { $time }
    .tooltip = tiempo de amortiguamiento: el tiempo en que la oscilación se reduce un factor e = 2.72
card-neutral = neutro: ni crecimiento ni amortiguamiento
card-mode = modo { $k } de { $n }
card-the-mode = el modo
card-frequency = frecuencia  { $frequency } rad/s  (periodo { $period } s{ $which })
    .tooltip = frecuencia: lo rápido que oscila la columna, en radianes por segundo (la altura del autovalor); el periodo es una oscilación completa. Una columna de n barras tiene n modos de oscilación, contados aquí desde el más lento; la tarjeta describe el que crece más rápido (o se amortigua más despacio), y la medida de la simulación se muestra para ese mismo modo
card-non-oscillatory = no oscilatorio: el autovalor dominante es real
card-measured = medido en la simulación{ $mode }  { $measurement }
    .tooltip = el autovalor ajustado al propio movimiento de la simulación (un haz de matrices de los ángulos): al menos 20 s de oscilaciones pequeñas (por debajo de 0.05 rad) desde el último golpe, suelta o cambio, cada modo cuando la simulación contiene un periodo entero suyo; «modo 2 de 2» cuenta los modos de oscilación de la columna desde el más lento. El ± es la incertidumbre propia del ajuste: cuánto se apartan los ajustes sobre los primeros y los últimos tres cuartos de la simulación del ajuste sobre toda ella. También el paso de tiempo dt del integrador aparta la simulación del modelo lineal, su frecuencia en unos ω³dt²/24
card-measured-other-mode = medido en la simulación: solo { $mode }, { $measurement } ({ $card } de la tarjeta, demasiado débil en esta simulación para ajustarlo)
card-measured-other = medido en la simulación: solo otro autovalor, { $measurement } (el de la tarjeta, demasiado débil en esta simulación para ajustarlo)
card-measured-after = medido: tras 20 s de movimiento de pequeña amplitud (|φ| < 0.05 rad)
card-measured-two-rods = medido: solo con dos barras (los muchos modos lentos de una cadena necesitan una simulación más larga de la que un ajuste puede usar)
card-measurement = crecimiento { $growth } 1/s, frecuencia { $frequency } rad/s
card-measurement-unknown = crecimiento { $growth } 1/s, frecuencia { $frequency } rad/s (incertidumbre desconocida: muy pocos periodos en la simulación)
card-grows-slowly = crece un { $percent } por periodo: observa durante minutos, no segundos
card-grows-too-slowly = crece un { $percent } por periodo: demasiado lento para verlo en una lección
onset-soft = inicio suave en p = { $at }: la oscilación se asienta en un ciclo límite que crece desde cero
onset-soft-roller = inicio suave en p = { $at }: un ciclo crece desde cero, hasta que el rodillo se acerca a la adherencia
onset-hard = inicio brusco en p = { $at }: la oscilación salta a un ciclo grande, que persiste por debajo del inicio
onset-degenerate = inicio en p = { $at } ni suave ni brusco a primer orden
onset-reversible = sin amortiguamiento: no hay ciclo límite en el que asentarse (una columna reversible)
    .tooltip = Sin amortiguamiento la columna es reversible: el flameo empieza donde dos pares de autovalores se encuentran sobre el eje imaginario, y no hay atractor, así que no hay ciclo límite en el que la oscilación pueda asentarse.
onset =
    .tooltip = Suave: pasado el inicio la oscilación crece desde cero hasta un ciclo estacionario pequeño, mayor al subir la carga; brusco: salta a uno grande, que permanece cuando la carga baja un poco. Adherencia: el rodillo deja de deslizar sobre la banda, donde el rozamiento cambia de ley.{"\u000A"}{"\u000A"}Primer coeficiente de Liapunov { $lyapunov } en el inicio p = { $at } (punto de Hopf, frecuencia { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = Cerca de él, |phi1| del ciclo vale unos { $a } sqrt(p - { $at }) rad.
onset-sticking = Sobre el rodillo el deslizamiento en el contacto disminuye a medida que crece el ciclo; donde se acerca a cero el rozamiento deja de ser suave y el movimiento pasa a stick-slip, que este análisis no sigue: la rama de la pestaña poscrítico termina ahí.

## The load ramp

ramp = rampa de carga
ramp-from = de
    .name = rampa desde
    .tooltip = la carga en la que empieza la rampa
ramp-to = a
    .name = rampa hasta
    .tooltip = la carga en la que se detiene la rampa
ramp-rate = a razón de
    .name = ritmo de la rampa
    .tooltip = lo rápido que cambia la carga, por segundo simulado
ramp-start = iniciar rampa
    .tooltip = la carga va a «de» y se mueve hacia «a» al ritmo dado, mientras la simulación sigue (fijar la carga a mano la termina)
ramp-pause = pausar rampa
    .tooltip = mantener la carga donde está; la simulación sigue
ramp-resume = reanudar
ramp-stop = parar
    .tooltip = terminar la rampa
ramp-done = terminada
ramp-paused = en pausa
ramp-moving = en marcha
ramp-progress = p = { $load } hacia { $to } a { $rate }/s ({ $doing })

## Sharing the settings

share-copy = copiar ajustes
    .tooltip = el modelo, la carga, el integrador y la velocidad como texto, al portapapeles y al cuadro de abajo
share-paste = pegar del portapapeles
    .tooltip = tomar un texto de ajustes copiado en otro sitio (el cuadro de abajo lo muestra)
share-box = o escribe o pega aquí un texto de ajustes
share-take = usar el texto de arriba
    .tooltip = cargar los ajustes escritos en el cuadro
paste-too-long = pegado rechazado, nada ha cambiado: el texto tiene { $bytes } bytes; ningún campo de aquí admite más de { $most } (un texto de ajustes tiene menos de 2000)
paste-no-text = pegar ajustes: el portapapeles no contiene texto (copia primero el texto de ajustes)

## Lessons

lessons = lecciones
lessons-built-in = la lección incluida { $name }
lesson-file = archivo de lección
    .hint = un archivo de lección (.ron)
    .tooltip = la ruta de tu propio archivo de lección (el formato está en el README)
lesson-open = abrir
    .tooltip = leer y comprobar el archivo, y luego empezarlo
lesson-reading = leyendo { $path }
lesson-reading-stopped = { $path }: la lectura se detuvo sin respuesta
lesson-step = paso { $k } de { $n }
lesson-prediction = tu predicción: p = { $load }
lesson-predicted-load = carga prevista
    .tooltip = dónde la esperas; la barra de carga la marca (teclas como en la barra de carga: izquierda, derecha, mayús para diez pasos, inicio, fin)
lesson-back = atrás
    .tooltip = el paso anterior (Re Pág)
lesson-next = siguiente
    .tooltip = el paso siguiente: ajusta e inicia lo que dice (Av Pág, como envía el mando de un presentador)
lesson-close = cerrar lección
    .tooltip = salir de la lección; el modelo queda como está
lesson-next-lesson = lección siguiente: { $title }
    .tooltip = abrir la lección siguiente, «{ $title }», en su primer paso (Av Pág)
lesson-last = el último paso de la última lección

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = carga p = P l/k
axis-largest-angle = mayor |φ_i| en un ciclo (rad)
axis-damping-level = amortiguamiento g2 = c2 / √(k m l²)
axis-mass-ratio = relación de masas m1 / (masa más allá de la articulación A)
axis-log-scale = { $axis } (escala logarítmica)
axis-first-critical-load = primera carga crítica p
mark-load = carga
locus-far-left = { $name }: autovalores hasta Re λ = { $re } 1/s (modos que se amortiguan deprisa) quedan a la izquierda de la vista, que contiene los que deciden la estabilidad
legend-branch-colour = color de las ramas: la carga, p = de { $from } a { $to }
legend-eigenvalues-now = autovalores con la carga actual
legend-measured = medidos en la simulación
legend-current-load = carga actual
legend-overlay-no-change = ningún cambio de estabilidad hasta el final del deslizador
legend-overlay = comparación { $name }: { $loads }
legend-transition = p = { $load }: de { $from } a { $to }
legend-more-loads = { $count ->
    [one] { $count } carga crítica más (zieglerlab critical las lista)
   *[other] { $count } cargas críticas más (zieglerlab critical las lista)
}
legend-no-analysis = sin análisis
legend-stronger = más intenso: crecimiento o amortiguamiento más rápido (máximo: { $largest } 1/s)
legend-critical-loads = cargas críticas
legend-now = ahora
legend-now-off = ahora: fuera del mapa ({ $why })
legend-now-no-value = ahora: no está en el mapa ({ $axis } no tiene valor para esta columna)
legend-now-below = { $name } = { $value } está por debajo de { $bound }
legend-now-above = { $name } = { $value } está por encima de { $bound }
legend-this-model = este modelo: p = { $load }
legend-straight-stable = columna recta, estable
legend-straight-unstable = columna recta, inestable
legend-stable-cycle = ciclo límite estable
legend-unstable-cycle = ciclo límite inestable
legend-hopf-point = inicio del flameo (punto de Hopf)
legend-cycle-fold = LPC: pliegue de ciclos
legend-cycle-period-doubling = PD: duplicación del periodo
legend-cycle-torus = NS: toro (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC: ruptura de simetría (punto de ramificación de ciclos)
legend-sweep-up = barrido hacia arriba (una simulación)
legend-sweep-down = barrido hacia abajo (una simulación)
legend-seen-in-ramp = visto durante la rampa
legend-largest-angle = mayor ángulo de esta simulación, último periodo
legend-flutter-soft = inicio del flameo, suave: crece una oscilación pequeña
legend-flutter-hard = inicio del flameo, brusco: salto a una oscilación grande
legend-divergence-onset = inicio de la divergencia
legend-special-points = B: Bautin (de suave a brusco), BT: Bogdanov-Takens, DH: doble Hopf, ZH: cero-Hopf
legend-fold-of-cycles = pliegue de ciclos: por debajo ninguna oscilación sobrevive
legend-hysteresis = histéresis: reposo y oscilación grande, ambos estables
describe-against = { $y } frente a { $x }
describe-range = { $state } de { $from } a { $to }
describe-ranges = intervalos: { $ranges }
describe-mark = { $name } en { $x }
describe-marked = marcados: { $marks }
describe-point = { $name } en ({ $x }, { $y })
describe-points = con nombre: { $points }
describe-bands = sombreada entre un pliegue de ciclos y un inicio brusco del flameo: la banda de histéresis, donde reposo y oscilación grande son ambos estables
describe-curves = { $count ->
    [one] { $count } curva
   *[other] { $count } curvas
}
describe-now-stable = con la carga actual los { $count } autovalores quedan a la izquierda del eje imaginario: un golpe se amortigua
describe-now-flutter = con la carga actual { $right } de { $count } autovalores quedan a la derecha del eje imaginario, { $oscillating } de ellos fuera del eje real: una oscilación crece (flameo)
describe-now-divergence = con la carga actual { $right } de { $count } autovalores quedan a la derecha del eje imaginario, ninguno fuera del eje real: la columna se dobla (divergencia)
describe-map = un mapa de { $columns } por { $rows } celdas: estable { $stable } %, flameo { $flutter } %, divergencia { $divergence } %

## The scene, the load bar and the tabs' own words

scene-name = la columna
scene-swing = su oscilación ahora { $rad } rad
scene-hidden = la columna, { $swing }
scene-analysing = la columna, { $swing }; se está analizando su estabilidad
scene-stable = estable: un golpe se amortigua, hasta una centésima en { $secs } s; { $swing }
scene-undamped = estable pero sin amortiguamiento: un golpe sigue oscilando, sin crecer ni amortiguarse; { $swing }
scene-flutter = la columna entra en flameo: una oscilación crece, duplicándose cada { $secs } s a { $frequency } rad/s; { $swing }
scene-divergence = divergencia: la columna se dobla alejándose de la recta, duplicándose cada { $secs } s; { $swing }
scene-stopped = la simulación se detuvo: { $status }; R empieza una nueva
scene-drag-hint = arrastra el extremo o una articulación para desplazar la columna
scene-whole-reach = alcance total
    .tooltip = encuadrar todo el disco que el extremo puede alcanzar, quieto; apagado, la vista sigue el movimiento, alejándose en cuanto la columna oscila mucho y acercándose cuando se calma, siempre con el empotramiento a la vista
scene-delta =
    .tooltip = δ: el ángulo desde la dirección de la última barra (la flecha discontinua, adonde apuntaría una fuerza seguidora ideal) hasta la fuerza que aplica de verdad el rozamiento de la banda (la flecha continua), dibujado como el arco del extremo. δ = 0 es una seguidora perfecta; el rodillo gira la fuerza δ al deslizar de lado sobre la banda (ec. 23)
scene-stick-slip = stick-slip: la velocidad de deslizamiento es menor que 1e-4 m/s; el rozamiento de Coulomb está regularizado aquí, fuera de la validez del modelo
scene-band = banda moviéndose a la izquierda a V = { $speed } m/s
load-bar = carga{"\u000A"}p = { $load }
    .name = deslizador de carga
    .tooltip = la carga p = P l/k: haz clic o arrastra aquí, o usa las flechas (con la barra enfocada: izquierda y derecha, mayús para diez pasos, inicio y fin)
load-bar-said = carga p = { $load } de 0 a { $end }
load-bar-said-hidden = { $load }: el estado está oculto hasta que la lección lo revele
load-bar-said-analysing = { $load }: analizando
load-bar-said-range = { $load }: { $state }, de p = { $from } a { $to }
load-bar-said-beyond = { $load }: fuera del intervalo analizado
view-hint = arrastrar: desplazar · Ctrl+rueda: ampliar · doble clic: ajustar
    .more = Mostrar de nuevo todos los datos (como un doble clic en un gráfico).{"\u000A"}Arrastra o desplaza para mover, Ctrl+rueda para ampliar, arrastra un recuadro con el botón derecho para ampliarlo.
view-fit = ajustar
map-readout-growth = tasa de crecimiento { $rate } 1/s
map-kick-settles = un golpe se amortigua
map-kick-hysteresis = un golpe pequeño se amortigua, uno grande lo deja oscilando (histéresis)
map-kick-grows-softly = un golpe crece suavemente hasta una oscilación pequeña
map-kick-jumps = un golpe salta a una oscilación grande
map-following = siguiendo el borde del flameo y los pliegues de ciclos…
map-not-followed = bordes no seguidos: { $why }
map-readout-hint = señala el mapa para leer una celda; haz clic para tomar su carga y su parámetro
histories-delta = δ: el ángulo de la fuerza de la banda respecto a la barra 2
histories-energy = energía cinética + elástica
histories-band-power = potencia de la banda
histories-rod-2 = barra 2
zoom-outside = el zoom { $zoom } está fuera de { $least } a { $most }: fijado en { $held } (Ctrl+0: 100%)
plot-name = gráfico: { $y } frente a { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Calculando el lugar de las raíces de estos parámetros...
locus-none = No hay lugar de las raíces para estos parámetros.
locus-none-why = No hay lugar de las raíces para estos parámetros: { $why }.
locus-title = lugar de las raíces, p = de { $from } a { $to }
map-rows = filas { $done } de { $total }
map-grey-rows = las filas grises no tienen análisis: { $why }
map-empty-range = el rango del mapa de { $lo } a { $hi } está vacío
map-no-thread = no hay hilo para el mapa: { $why }
map-stopped = el mapa se detuvo: { $why }
map-axis = carga p frente a
    .tooltip = el segundo parámetro del mapa (su intervalo de abajo reinicia el mapa)
map-from = de
    .name = intervalo del mapa desde
    .tooltip = dónde empieza el segundo parámetro
map-to = a
    .name = intervalo del mapa hasta
    .tooltip = dónde termina el segundo parámetro
paradox-computing = calculando las cargas de flameo a medida que el amortiguamiento desaparece ...
paradox-joints = La carga de flameo con amortiguadores en las articulaciones c1 = (c1/c2) c2 cuando el nivel de amortiguamiento g2 = c2 / sqrt(k m l^2) tiende a cero: el límite depende de la relación y queda por debajo de la carga sin amortiguamiento (paradoja de Ziegler).
paradox-external = La carga de flameo con amortiguadores iguales en las articulaciones c1 = c2 = c (amortiguamiento interno) y resistencia c_ext = (c_ext l^3 / c) c / l^3 a lo largo de las barras (amortiguamiento externo) cuando el nivel g2 = c / sqrt(k m l^2) tiende a cero: el amortiguamiento externo también desestabiliza, y el límite depende de la relación.
paradox-no-extent = las curvas no tienen extensión a lo largo de la relación
paradox-no-thread = no hay hilo para las curvas: { $why }
paradox-dead-load = Una carga muerta (eta = 0) es conservativa: nunca flamea, así que no hay paradoja que mostrar.
paradox-stable-throughout = No hay curva que dibujar: en cada relación mostrada la columna conserva su estabilidad hasta p = { $end }.
paradox-failed = No hay curva que dibujar: { $why }.
paradox-kind = amortiguamiento que desaparece:
paradox-kind-joints = amortiguadores en las articulaciones
    .tooltip = los amortiguadores de las articulaciones c1 y c2 en la relación c1/c2
paradox-kind-external = resistencia externa e interno
    .tooltip = resistencia c_ext a lo largo de las barras (externa) y amortiguadores iguales en las articulaciones c1 = c2 = c (interno) en la relación c_ext l^3 / c
paradox-roller = La carga con la que la columna con rodillo pierde primero la estabilidad, frente a la masa del rodillo, para tres velocidades de la banda (el amortiguamiento por deslizamiento es mu R / V).
paradox-roller-falling = bajando hacia cero cuando nu -> 0
paradox-roller-flat = sin bajar hacia cero en este intervalo
paradox-roller-massless = ; el rodillo sin masa (la seguidora ideal) pierde la estabilidad en p = { $load }
paradox-roller-caption = { $intro } Con la menor masa mostrada, nu = { $nu }, las curvas están en { $at }, { $trend }{ $massless }.
record-next = los próximos
record-secs = s en
    .name = segundos a grabar
    .tooltip = segundos de la ventana que se graban (de 1 a 60)
record-folder =
    .name = carpeta de la grabación
    .tooltip = la carpeta donde va el GIF
record-choosing = eligiendo...
record-choose = elegir...
    .tooltip = elegir la carpeta en el diálogo del escritorio
    .title = zieglerlab: la carpeta de las grabaciones
record-start = grabar
    .tooltip = grabar lo que muestra la ventana, 10 fotogramas por segundo, en un GIF
    .no-folder = la carpeta no existe

## A lesson's revealed results

reveal-never = la columna no pierde la estabilidad hasta p = { $load }
reveal-theory = la teoría: inestable desde p = { $load }
reveal-seen = ; el movimiento apareció en p = { $load }
reveal-predicted = Predijiste p = { $load };{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Correcto: elegiste «{ $chosen }», la respuesta.
reveal-wrong = Esta no: elegiste «{ $chosen }»; la respuesta es «{ $answer }».
reveal-answer = La respuesta: «{ $answer }».
reveal-no-answer = la teoría no tiene respuesta con esta carga
reveal-period = , un periodo de { $secs } s
reveal-flutter = flameo: la oscilación se duplica cada { $secs } s{ $period }
reveal-divergence = divergencia: la inclinación se duplica cada { $secs } s
reveal-stable = estable: un golpe se reduce a la mitad cada { $secs } s{ $period }
reveal-undamped = estable: un golpe ni crece ni se amortigua{ $period }
reveal-here = La teoría en p = { $load }: { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = barras = { $rods }: la barra de carga va ahora de 0 a { $end }, y la carga se movió con ella de p = { $from } a { $to } (el mismo lugar de la barra; escribe la carga para fijar otra)
notice-rods-load-kept = barras = { $rods }: se mantiene la carga p = { $load } ({ $why })
notice-switched-to-reference = la columna es demasiado rígida para el integrador rapier con su paso de 1/240 s (amortiguamiento o rigidez enormes frente a poca masa); se cambió al integrador de referencia
notice-lesson-last-step = este era el último paso de la lección: ciérrala, o abre otra desde el menú lecciones
notice-paste-nothing = nada que pegar: copia antes un texto de ajustes («copiar ajustes» en el menú compartir), o escríbelo en el cuadro
notice-paste-not-understood = ajustes pegados rechazados, nada ha cambiado: no se entendió { $what }
notice-pasted = ajustes pegados
notice-not-saved = no guardado: no se eligió ningún archivo (donde no se abrió un diálogo, este escritorio no ofrece ninguno)
recording-saved = grabación guardada en { $path }: { $frames } fotogramas en { $secs } s{ $slow }
recording-jerky = ; solo capturó { $caught } fotogramas por segundo de los { $fps } por segundo del GIF (el ritmo de captura: la máquina estaba demasiado ocupada para tomar más), así que el GIF va a la velocidad correcta pero a saltos: una ventana más pequeña (o el modo proyector apagado) graba más
recording-title = { $title }: grabando, faltan { $secs } s
recording-making = creando el GIF: fotograma { $done } de { $kept }
save-as = guardar como
    .path = ruta donde guardar
save-as-typed = No se abrió ningún diálogo de archivos en este escritorio: escribe dónde guardar { $what }.
save-as-exists = { $path } ya existe: ¿reemplazarlo? (guarda otra vez para reemplazar)
save-as-replace = reemplazar
save-as-save = guardar
save-as-cancel = cancelar
save-as-what-table = la tabla (CSV)
save-as-what-plots = los gráficos (PNG)
save-as-no-path = escriba la ruta de un archivo
save-as-no-folder = su carpeta no existe
save-as-folder = es una carpeta: escriba en ella el nombre de un archivo
save-as-pipe = es una tubería o un dispositivo, no un archivo: escriba la ruta de un archivo
save-as-protected = el archivo existe y no se puede escribir ({ $why }); se deja como estaba

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (externo / interno)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = amortiguamiento g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds }: una curva, la primera carga crítica no depende de V
paradox-reference-undamped = sin amortiguamiento
paradox-reference-massless = nu = 0: la seguidora ideal
paradox-reference = { $name }: p = { $load }
paradox-reference-above = { $name }: p = { $load } (por encima del eje)

## Refused values and the engine's failures

refused-value = { $subject } = { $value }: { $allowed }
refused-not-a-number = '{ $text }' no es un número
refused-unknown-preset = preajuste desconocido '{ $name }'; los preajustes son: { $known }
refused-unknown-key = clave desconocida '{ $key }'; las claves son: { $known }
refused-malformed = '{ $text }' no es clave=valor con un número (p. ej. load=2.5): { $reason }
refused-conflict = { $first } y { $second } fijan la misma magnitud; indique solo una
allowed-finite = debe ser un número finito
allowed-positive = debe ser > 0
allowed-non-negative = debe ser >= 0
allowed-key-range = debe ser un número finito { $range } { $unit }
allowed-key-count = debe ser un número entero { $range }
allowed-between = debe estar entre { $min } y { $key } = { $max }
allowed-rods = debe ser un número entero de 2 a { $most }
allowed-eta-range = debe estar entre 0 (carga muerta) y 1 (fuerza seguidora)
allowed-frictionless-band = debe ser > 0: sin rozamiento la banda no ejerce carga alguna (para una columna sin carga, ponga la carga a 0)
allowed-friction-too-small = demasiado pequeño: la carga p = { $load } necesitaría una fuerza normal R = P / mu más allá de todo número
allowed-beyond-analysis = más allá de lo que el análisis puede elevar al cuadrado (magnitudes de { $smallest } a { $largest })
allowed-makes-beyond-analysis = lleva { $what } más allá de lo que el análisis puede elevar al cuadrado (magnitudes de { $smallest } a { $largest })
allowed-masses-too-unequal = las masas son demasiado desiguales: el determinante de la matriz de masas está por debajo de 1e-12 de su escala, así que el redondeo decide el movimiento (p. ej. una masa en la punta o un rodillo de más de unas 1e12 veces la de las barras)
allowed-mass-missing = la columna necesita masa más allá de la articulación A (barra 2, punta o rodillo) y masa o inercia que se mueva solo con la barra 1; la matriz de masas es singular
allowed-chain-massless = una cadena necesita masa o inercia en cada copia de la barra 2 (m2 o I2 > 0): con la barra 2 sin masa la matriz de masas de la cadena es singular
allowed-needs-damped-joint2 = necesita una articulación 2 amortiguada: fije antes c2 > 0 (o el nivel de amortiguamiento)
allowed-infinite-damper-ratio = c2 = 0 con c1 > 0: la relación c1/c2 que mantener es infinita; fije antes c2 > 0
allowed-band-at-rest = debe ser > 0 para el análisis lineal: con V = 0 el rozamiento de Coulomb no es derivable en torno al reposo (stick-slip)
allowed-roller-has-no-eta = el rodillo no tiene eta: el rozamiento de la banda da la dirección de la fuerza, contra el deslizamiento en el contacto, y su ángulo delta respecto de la barra 2 es un resultado del movimiento, no un parámetro
allowed-state-length = debe ser 2 (barras + 1): los ángulos, el giro y sus velocidades
allowed-time-step = debe ser un paso de tiempo en (0, 1] s
quantity-load-force = la carga P
quantity-load-p = la carga p = P l/k
quantity-inertia-o = la inercia respecto de O
quantity-inertia-coupling = la inercia de acoplamiento
quantity-inertia-a = la inercia respecto de A
quantity-stiffness-k1 = la rigidez k1
quantity-stiffness-k2 = la rigidez k2
quantity-damper-c1 = el amortiguador c1
quantity-damper-c2 = el amortiguador c2
quantity-drag = el arrastre c_ext l^3
quantity-slip-damping = el amortiguamiento de deslizamiento mu R l^2 / V
quantity-spin-inertia = la inercia de giro del rodillo m3 r^2 / 2
quantity-mass-matrix = la matriz de masas
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = la longitud del estado
quantity-time-step = dt
engine-too-stiff = el motor rapier no puede integrar esta columna con dt = { $step } s: sus resortes y amortiguadores alcanzan tasas de { $rate } 1/s, que necesitan dt < { $need } s; use el motor de referencia
engine-rapier-world = no se pudo construir el mundo rapier2d para esta columna (sus articulaciones fueron rechazadas); use el motor de referencia
analysis-not-converged = la iteración de autovalores no convergió con la carga p = { $load }
ramp-refused-end = { $end } = { $value }: debe ser una carga p >= 0
ramp-refused-rate = ritmo de la rampa = { $value }: debe ser una carga positiva por segundo
ramp-refused-too-slow = ritmo de la rampa = { $value }: debe ser al menos { $slowest } de carga por segundo (más lento, la carga no se movería visiblemente en días)
ramp-refused-too-long = la rampa de { $from } a { $to } a { $rate } por segundo tarda { $secs } s de tiempo simulado; como mucho { $most } s (unos cuatro meses): un ritmo mayor o extremos más cercanos
ramp-refused-model = { $end } = { $value }: { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = rampa: { $why }
notice-ramp-stopped = rampa detenida: { $why }
notice-map-point-refused = mapa: { $why }
notice-overlay-unavailable = superposición no disponible: { $why }
notice-table-not-saved = no guardado: { $why }
notice-no-locus = no hay lugar de las raíces para estos parámetros
notice-no-thread = no guardado: no hay hilo para escribir ({ $why })
notice-saved-lines = { $count ->
    [one] guardada { $count } línea
   *[other] guardadas { $count } líneas
} en { $path }
notice-write-failed = no guardado: { $why }
notice-plots-saved = gráficas guardadas en { $path }
notice-plots-not-saved = gráficas no guardadas: { $why }
notice-recording-failed = la grabación falló: { $why }
notice-layout-not-saved = disposición de la ventana no guardada: { $why }
notice-stored-overlay = la superposición guardada { $name } no es un preajuste; sin superposición
notice-stored-map-axis = no se usa el eje del mapa guardado: { $why }
notice-stored-language = no se usa el idioma guardado: { $why }
notice-lesson-refused = lección { $name }: { $why }
notice-lesson-not-opened = lección no abierta: { $why }
notice-reset-closed-lesson = todo restablecido: la lección "{ $title }" está cerrada (ábrala de nuevo desde el menú de lecciones)

## The post-critical tab's notes

cycles-computing = siguiendo los ciclos límite desde cada inicio del flameo ...
cycles-none = no hay ciclos límite: { $why }
cycles-no-onset = ningún inicio del flameo en el rango de la barra de carga: no hay ciclos límite
cycles-chain-too-long = una cadena de { $rods } barras tarda demasiado en seguirse en la ventana (16 barras tardan unos 20 s en dos núcleos, y el trabajo crece más deprisa que el número de barras); `zieglerlab bifurcation` calcula sus ciclos desde la línea de órdenes
cycles-no-thread = no hay hilo para los ciclos: { $why }
cycles-branch = { $name }: inicio { $onset } en p = { $at }; la rama terminó: { $end }
cycles-offshoot = { $name }: ciclos asimétricos (y sus imágenes especulares) desde el BPC en p = { $at }; la rama terminó: { $end }
cycles-onset-soft = suave
cycles-onset-hard = brusco
cycles-no-branch = inicio del flameo en p = { $at }: { $why }
cycles-no-branch-reversible = sin amortiguamiento, una columna reversible: ningún ciclo límite que seguir
cycles-no-branch-degenerate = el primer coeficiente de Liapunov es cero dentro de su precisión; ciclos no seguidos
cycles-no-branch-not-converged = el método de disparo no convergió cerca del inicio; no hay ciclos
cycles-end-left-range = salió del rango de cargas
cycles-end-large-amplitude = la amplitud de un ángulo superó { $most } rad (la columna da la vuelta)
cycles-end-long-period = el periodo creció más de { $most } veces el del inicio
cycles-end-lost = el método de disparo no convergió más allá de p = { $load }
cycles-end-stick-slip = el contacto del rodillo se acerca a adherirse a la banda más allá de p = { $load } (stick-slip: allí el rozamiento no es suave)
cycles-end-unresolved = los ciclos más allá de p = { $load } no están resueltos (multiplicador trivial alejado de 1 más de { $tolerance })
cycles-end-point-limit = { $most } ciclos calculados
cycles-end-cancelled = detenido a petición

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = la estabilidad no está resuelta: en p = { $load } los modos van de { $fastest } 1/s a { $slowest } 1/s, una relación mayor que { $span }, así que las tasas de crecimiento de los modos lentos quedan al redondeo (un modo mucho más rápido que los demás, como el giro de un rodillo de masa nu diminuta)
not-resolved-slow-mode-lost = la estabilidad no está resuelta: en p = { $load } los modos van de { $scale } 1/s a { $slowest } 1/s, así que las tasas de crecimiento por debajo de { $tolerance } 1/s se pierden en el redondeo (el modelo está cerca de un límite singular: una banda V muy lenta o un amortiguamiento muy grande)
not-resolved-methods-disagree = la estabilidad no está resuelta: en p = { $load } las raíces seguidas y la descomposición de Schur no coinciden en el estado (lo decide el redondeo: un modo mucho más rápido que los demás, como el giro de un rodillo de masa nu diminuta); las cargas críticas mostradas pueden ser espurias o faltar
not-resolved-rounding-decides = la estabilidad no está resuelta: para p de { $low } a { $high } las tasas de crecimiento están entre 1e-12 y 1e-10 de la escala de frecuencias, donde el redondeo decide el estado (un rodillo de masa nu diminuta, cuyo débil flameo crece en proporción a nu, o una banda V muy lenta); las cargas críticas mostradas pueden estar desplazadas o faltar
not-resolved-refinement-cut = el lugar de las raíces se refinó solo hasta p = { $load }: más allá las ramas se muestrean solo en las cargas equiespaciadas, así que puede faltar una ventana de otro estado más estrecha que su separación (se alcanzó el límite de tiempo y memoria del refinamiento)

## The stored state's check before the window opens (a damaged store)

store-zoom = el factor de zoom { $zoom } (se admite de 0.2 a 5)
store-geometry = la geometría de la ventana { $width } x { $height } puntos a escala { $scale }
store-unreadable = no se pudo leer el estado guardado ({ $why }); se guarda una copia en { $copy }; se empieza con los valores predeterminados
store-unreadable-uncopied = no se pudo leer ({ $why }) ni copiar ({ $error })
store-moved = el estado guardado { $path } { $why }; se traslada a { $aside } y se usan los valores predeterminados
store-not-moved = el estado guardado { $path } { $why } y no se pudo apartar ({ $error }); los ajustes no se guardarán
store-folder-not-made = los ajustes no se guardarán: no se puede crear la carpeta { $folder } ({ $error })
store-folder-full = los ajustes no se guardarán: la carpeta { $folder } no admite archivos nuevos ({ $error })
store-not-writable = los ajustes no se guardarán: no se puede escribir { $path } ({ $error })
store-is-folder = es una carpeta
store-is-device = es un dispositivo, una tubería o un socket
store-too-large = contiene { $bytes } bytes (se leen como mucho { $most })
store-entry = { $why } (entrada '{ $key }' de eframe)
store-ignored = estado guardado: se ignora { $what }
store-ignored-not-rewritten = estado guardado: se ignora { $what } (no se pudo reescribir el archivo: { $error })
store-settings-unreadable = no se pudieron leer los ajustes guardados
store-original-kept = el original se guarda en { $copy }
store-original-lost = no se pudo guardar una copia del original ({ $error })
store-settings-partly = ajustes guardados: se ignora { $what }; se mantiene el resto
store-settings-ignored = ajustes guardados ignorados ({ $why }); se empieza con los valores predeterminados
layout-ignored = disposición de ventana guardada ignorada ({ $why }); se usa la disposición predeterminada
notice-paste-unreadable = ajustes pegados no entendidos, no ha cambiado nada: { $why }
notice-paste-refused = ajustes pegados rechazados, no ha cambiado nada: { $why }
notice-analysis-unavailable = análisis no disponible: { $why }
notice-lesson-step = paso { $step } de la lección: { $why }
notice-lesson = lección: { $why }
