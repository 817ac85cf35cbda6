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
