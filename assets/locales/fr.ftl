### zieglerlab : les textes de la fenêtre en français.
###
### Les mêmes messages que en.ftl, avec les mêmes paramètres ; les nombres
### arrivent déjà écrits, avec un point décimal comme en ligne de commande.
###
### Glossaire (partout le même) :
###   flutter : flottement (instabilité dynamique)   divergence : divergence
###   follower force : force suiveuse                dead load : charge morte
###   critical load : charge critique                root locus : lieu des racines
###   eigenvalue : valeur propre                     growth rate : taux de croissance
###   damping : amortissement                        limit cycle : cycle limite
###   Hopf bifurcation : bifurcation de Hopf (apparition douce / brutale)
###   rod : barre     column : colonne               spring : ressort de torsion
###   roller : galet  moving band : bande mobile     friction : frottement
###   stability map : carte de stabilité             Ziegler's paradox : paradoxe de Ziegler

## Counts

rods-count = { $count ->
    [one] { $count } barre
   *[other] { $count } barres
}

## The sidebar's heading and its menus

menu-share = partager
    .tooltip = les réglages en texte : les copier, ou en coller
menu-record = enregistrer
    .tooltip = enregistrer la fenêtre dans un GIF
menu-keys = touches
    .tooltip = les commandes du clavier
menu-language = la langue de la fenêtre (retenue pour le prochain lancement)
    .name = langue : { $language }
projector-toggle = projecteur (P)
overlay = comparer
    .none = aucun
    .tooltip = le lieu des racines d'un autre modèle en gris, au même a (comme la fig. 8 place la colonne idéale à côté du galet)
section-parameters = paramètres

## The status line at the window's foot

status-dismiss = fermer
    .tooltip = effacer ce message
status-latest = le dernier message (le texte entier)
status-got-it = compris
    .tooltip = masquer l'astuce
status-ready = prêt
hint-first-launch = Faites glisser la barre de charge vers 3 environ et appuyez sur K pour pousser la colonne (la barre d'espace met en pause).

## The tabs

tab-locus = lieu des racines
    .tooltip = le lieu des racines : les valeurs propres de la colonne dans le plan complexe et en fonction de la charge. À gauche de l'axe vertical un mouvement s'amortit, à droite il croît ; la hauteur est la fréquence. Le flottement commence où une paire traverse l'axe
tab-histories = évolutions temporelles
    .tooltip = les angles, l'énergie et la puissance de la bande au cours de la simulation
tab-map = carte de stabilité
    .tooltip = la stabilité de chaque charge en fonction d'un second paramètre
tab-paradox = paradoxe
    .tooltip = la première charge critique quand l'amortissement (ou la masse du galet) tend vers zéro
tab-post-critical = postcritique
    .tooltip = au-delà du début du flottement : la taille des cycles limites en fonction de la charge, stables ou non, et l'oscillation de la colonne elle-même
save-png = enregistrer PNG...
    .tooltip = ces graphiques en image, sans boutons ni astuces
save-csv = enregistrer CSV...
    .tooltip = les nombres derrière ces graphiques, dans les colonnes de la ligne de commande, dans un fichier
answer-hidden = Ce graphique montre la réponse : il revient quand la leçon la révèle.
answer-hidden-histories = { answer-hidden } Les évolutions temporelles montrent ce que fait la colonne.
tab-in-column-place = L'onglet « { $tab } » est à la place de la colonne ; l'onglet lieu des racines ramène la colonne.
locus-beside-column = Le lieu des racines est à côté de la colonne ; un onglet choisi ici s'affiche à la place de la colonne.
plots-need-room = Les graphiques ont besoin de plus de place ici : une fenêtre plus haute, ou le mode projecteur désactivé (P).

## The welcome of a first launch

welcome-title = Bienvenue dans zieglerlab
welcome-column = Deux barres sur des ressorts sont encastrées à une extrémité. À l'autre extrémité, une force pousse le long de la dernière barre et tourne avec elle : une force suiveuse. Ici elle est réalisée comme au laboratoire, par un galet qu'une bande mobile entraîne.
welcome-states = Sous de petites charges, une poussée fait osciller la colonne faiblement : elle est stable. Au-delà d'une charge critique, elle flotte : elle oscille d'un côté à l'autre, de plus en plus fort. Sous des charges plus grandes encore, elle peut diverger : elle fléchit d'un côté sans osciller.
welcome-locus = Le lieu des racines montre en nombres (ses valeurs propres) comment la colonne bouge quand la charge croît. À gauche de l'axe vertical une oscillation s'amortit ; à droite, elle croît. La distance vers la droite est le taux de croissance, la hauteur la fréquence.
welcome-try = Faites glisser la barre de charge et regardez les deux : la colonne commence à flotter à la charge où les valeurs propres traversent l'axe.
welcome-first-lesson = commencer la première leçon
    .tooltip = quelques étapes : prédire où commence le flottement, puis regarder
welcome-explore = explorer seul
    .tooltip = fermer ; les leçons restent en haut du panneau latéral

## States and critical loads

state-stable = stable
state-flutter = flottement
state-divergence = divergence
transition = p = { $load } : { $from } -> { $to }
transition-meaning = p = { $load } : la colonne passe de { $from } à { $to } ; { $how }
    .to-flutter = au-delà de cette charge une paire de valeurs propres est à droite de l'axe imaginaire : une poussée devient une oscillation de plus en plus ample
    .to-divergence = au-delà de cette charge une valeur propre réelle est positive : la colonne penche sans osciller
    .to-stable = au-delà de cette charge aucune valeur propre n'est à droite de l'axe imaginaire : une poussée ne croît plus
duration-forever = jamais
duration-days = { $count ->
    [one] { $n } jour
   *[other] { $n } jours
}
duration-years = { $count ->
    [one] { $n } an
   *[other] { $n } ans
}

## The model and the engine

model = modèle
    .source = { $source } : où se trouve le modèle dans l'étude que suit ce programme (sa figure et ses équations)
preset-ziegler-1952 = Ziegler 1952
    .description = La colonne de Ziegler : barres sans masse, masse ponctuelle 2m à l'articulation A et m à l'extrémité, force suiveuse idéale
preset-uniform-rods = fig. 1a
    .description = Barres rigides homogènes de masse m (fig. 1a), force suiveuse idéale
preset-midpoint-masses = fig. 1b, éq. 1-7
    .description = Barres sans masse avec une masse ponctuelle m au milieu de chacune (fig. 1b, éq. 1-7), force suiveuse idéale
preset-roller = fig. 7, éq. 8-38
    .description = Barres homogènes avec un galet entraîné par une bande mobile (fig. 7, éq. 8-38), inertie de rotation cohérente ; paramètres de la fig. 8
preset-roller-as-printed = éq. 39, fig. 8
    .description = Le modèle du galet tel qu'imprimé dans l'éq. (39) : l'inertie de rotation multipliée par r/l2, une erreur de l'article ; paramètres de la fig. 8
preset-tabletop = rythme de cours
    .description = Une colonne de table pour un cours : barres homogènes de 25 cm et 100 g, ressorts de 0.0625 N m/rad (a = 10 1/s^2), force suiveuse idéale ; au-delà de p = 2.54 elle flotte avec une période d'environ 1.5 s
preset-tabletop-roller = rythme de cours
    .description = La colonne de table poussée par un galet de 10 g et de 2.5 cm de rayon sur une bande à 0.1 m/s (nu = rho = mu = 0.1) : un flottement faible dès p = 0.024 qui met des minutes à croître, un fort près de la charge de la colonne idéale
preset-beck = Beck 1952, une chaîne de 16 barres
    .description = La colonne de Beck comme une chaîne de 16 barres homogènes avec des ressorts k à chaque articulation (une poutre d'EI = k l, L = 16 l), force suiveuse : flottement à P L^2/EI = 18.78 (colonne continue de Beck : 20.05)
preset-pflueger = La colonne de Pflüger, une chaîne de 16 barres
    .description = La colonne de Pflüger : la chaîne de Beck de 16 barres avec une masse d'extrémité égale à la moitié de la masse de la colonne, force suiveuse : la masse d'extrémité abaisse la charge de flottement à P L^2/EI = 15.06
preset-beck-roller = La chaîne de Beck chargée comme chez Bigoni et al. 2018
    .description = La chaîne de Beck de 16 barres chargée par le galet sur la bande mobile (les groupes de l'article sur chaque barre : masse du galet 0.1 m, rayon 0.1 l, mu = 0.1, V = 0.1 m/s) : l'amortissement du glissement la fait flotter faiblement dès P L^2/EI = 0.025 (croissance sous 3e-4 1/s), et fortement dès environ 18.8, où flotte la chaîne sous force suiveuse
preset-pflueger-roller = La chaîne de Pflüger chargée comme chez Bigoni et al. 2018
    .description = La chaîne de Pflüger de 16 barres (masse d'extrémité égale à la moitié de celle des barres) chargée par le même galet sur la bande mobile : flottement faible dès P L^2/EI = 0.008 (croissance sous 4e-5 1/s), flottement fort dès 15.06, où flotte la chaîne sous force suiveuse
tip-force-dead = force à l'extrémité : une charge morte (eta = 0), de direction fixe, à la place de la force suiveuse du modèle
tip-force-partial = force à l'extrémité : en partie tangentielle, tournée de eta = { $eta } fois l'angle de la dernière barre (la force suiveuse du modèle a eta = 1)
engine = intégrateur
    .tooltip = ce qui intègre le mouvement : la simulation reprend là où elle en est
engine-rapier = rapier
    .tooltip = rapier : le moteur physique rapier2d, barres en solides rigides reliés par des charnières (un système multicorps), la rotation du galet implicite
engine-reference = référence
    .tooltip = Dormand-Prince 5(4) adaptatif sur les équations exactes

## The load

load-field = charge p = P l/k
    .tooltip = saisir une charge (Entrée applique, Échap rétablit) ; aussi au-delà de la fin de la barre
    .meaning = la charge sans unité : la force P à l'extrémité fois la longueur de barre l divisée par la raideur des ressorts k (la colonne de Ziegler flotte dès p = 2.09)
roller-load = galet : q = R l/k = p/μ = { $q }   (μ = { $mu })
    .tooltip = la charge propre du galet : la force R qui le presse sur la bande, dans les unités de p ; le frottement de la bande pousse avec μ R, donc p = μ q
notes-more = ... et { $count } de plus (survoler)
load-beyond-range = p = { $load } est au-delà de l'intervalle tracé (de 0 à { $end }) ; l'état ci-dessous est à p
critical-loads-hidden = Les charges critiques sont cachées jusqu'à ce que la leçon les révèle.
not-resolved = la stabilité n'est pas résolue ici (survoler pour savoir pourquoi)
ramp-visible = l'extrémité déplacée de { $percent } % de la longueur
ramp-theory = théorie (repère blanc) : instable dès p = { $load }
ramp-seen = vu (repère) : mouvement visible à p = { $load } ({ $visible })
ramp-seen-late = vu (repère) : mouvement visible à p = { $load }, en retard : survoler pour savoir pourquoi ({ $visible })
    .why = Il apparaît en retard : après le début, le mouvement a besoin de temps pour atteindre une taille visible, et la rampe avance pendant ce temps. Une rampe plus lente le montre plus près de la théorie.
ramp-watching = en attente d'un mouvement visible ({ $visible })

## The parameters

groups = groupes sans dimension
    .tooltip = les quelques combinaisons des valeurs SI qui décident du mouvement (a = k/(m l^2) fixe sa rapidité ; nu, rho, mu et V du galet sa masse, sa taille, son frottement et la vitesse de la bande) ; en changer un garde les autres
si-parameters = paramètres SI
mu-moves-load = (R fixé : déplace p)
key-allowed = { $description } (permis : { $range })
refused = refusé : { $why }
key-load = charge p = P l/k sur l'axe commun (P = mu R pour le galet ; l = l1, k = k1)
    .range = >= 0
key-a = a = k/(m l^2) : fixe k1 (et k2 dans le même rapport), garde p
    .range = > 0
key-nu = nu = m3/m, masse du galet sur masse de la barre
    .range = >= 0
key-rho = rho = r/l, rayon du galet sur longueur de la barre
    .range = dans (0, l2/l]
key-mu = coefficient de frottement ; seul mu R entre dans les équations, donc R est fixé et la charge p = mu R l/k varie
    .range = > 0
key-V = vitesse de la bande (elle avance vers -x) ; l'analyse linéaire exige V > 0
    .range = >= 0
key-l1 = longueur de la barre 1 (sa répartition de masse suit)
    .range = > 0
key-l2 = longueur de la barre 2 (sa répartition de masse suit)
    .range = > 0
key-m1 = masse de la barre 1, masses ponctuelles comprises (répartition conservée)
    .range = >= 0
key-m2 = masse de la barre 2 (répartition conservée)
    .range = >= 0
key-s1 = centre de masse de la barre 1, depuis l'encastrement O
    .range = dans [0, l1]
key-s2 = centre de masse de la barre 2, depuis l'articulation A
    .range = dans [0, l2]
key-I1 = moment d'inertie de la barre 1 autour de son centre de masse
    .range = >= 0
key-I2 = moment d'inertie de la barre 2 autour de son centre de masse
    .range = >= 0
key-m_tip = masse ponctuelle à l'extrémité B (la masse du galet est m3)
    .range = >= 0
key-k1 = ressort de torsion à l'encastrement O
    .range = > 0
key-k2 = ressort de torsion à l'articulation A
    .range = > 0
key-c1 = amortisseur visqueux à l'encastrement O
    .range = >= 0
key-c2 = amortisseur visqueux à l'articulation A
    .range = >= 0
key-c_ext = traînée visqueuse extérieure le long des deux barres (résistance de l'air, linéarisée) : une force par unité de longueur égale à c_ext fois la vitesse locale transverse de la barre
    .range = >= 0
key-rods = barres de la chaîne : la barre 1, puis des copies de la barre 2 avec le ressort et l'amortisseur de l'articulation A à chaque articulation ; la masse d'extrémité et la charge au bout de la dernière barre
    .range = de 2 à 64
key-P = intensité de la force à l'extrémité
    .range = >= 0
key-eta = tangentialité de la force à l'extrémité : sa direction tourne de eta fois l'angle de la dernière barre (1 : force suiveuse, 0 : charge morte)
    .range = dans [0, 1]
key-m3 = masse du galet (0 : sans masse, la force suiveuse idéale)
    .range = >= 0
key-r = rayon du galet
    .range = dans (0, l2]
key-R = force normale du galet sur la bande
    .range = >= 0

## Time

command-play = lecture
    .running = pause
    .tooltip = lecture / pause
command-load-up = charge +
    .tooltip = augmenter la charge d'un centième de la barre
command-load-down = charge -
    .tooltip = diminuer la charge d'un centième de la barre
command-kick = pousser
    .tooltip = poussée : chaque barre tournée de 0.03 rad
command-reset = relancer
    .tooltip = relancer : une nouvelle simulation depuis la perturbation standard
command-reset-all = tout réinitialiser
    .tooltip = tout réinitialiser : les paramètres et la charge du modèle, vitesse normale, une nouvelle simulation, les vues par défaut ; une leçon ouverte est fermée
command-projector = mode projecteur
    .tooltip = mode projecteur : fort contraste, grand texte
command-next = suivant
    .tooltip = l'étape suivante de la leçon (la télécommande d'un présentateur envoie Page suivante)
command-back = retour
    .tooltip = l'étape précédente de la leçon (Page précédente)
command-full-screen = plein écran
    .tooltip = plein écran : la fenêtre remplit l'écran (à nouveau pour sortir)
command-step = pas
    .tooltip = un pas de l'intégrateur (1/240 s), puis pause
key-space = espace
key-right = droite
key-up = haut
key-left = gauche
key-down = bas
key-page-down = page suivante
key-page-up = page précédente
focus-keys-tab = le contrôle suivant (maj+tab : le précédent)
    .keys = tab
focus-keys-ctrl-tab = l'onglet suivant (ctrl+maj+tab : le précédent)
    .keys = ctrl+tab
focus-keys-press = avec un bouton, une case, un choix ou un onglet ciblé : l'actionner (espace ne lance la lecture que si rien n'est ciblé)
    .keys = espace, entrée
focus-keys-slider = avec un curseur ciblé (la barre de charge, la prédiction) : le déplacer d'un centième ; maj : d'un dixième
    .keys = gauche, droite
focus-keys-column = avec la colonne ciblée (tab jusqu'à elle) : la tourner de 0.02 rad dans un sens ou l'autre, maj : 0.1 rad (le glisser au clavier)
    .keys = gauche, droite
focus-keys-ends = avec la barre de charge ou la prédiction ciblée : ses extrémités
    .keys = début, fin
focus-keys-plot = avec un graphique ciblé (tab jusqu'à lui) : déplacer d'un dixième, zoomer autour du centre ; entrée : une carte prend la cellule sous la croix
    .keys = flèches, +, -
focus-keys-escape = lâcher le focus (un champ de texte : annuler la saisie)
    .keys = échap
focus-keys-others = page suivante, page précédente, K, R, P et haut/bas marchent quel que soit le focus, sauf dans un champ de texte en cours d'édition
    .keys = les autres
pace-slow = Lent
    .tooltip = un quart du temps réel
pace-normal = Normal
    .tooltip = temps réel : une seconde simulée par seconde
pace-fast = Rapide
    .tooltip = quatre fois le temps réel
speed-factor = × vitesse
    .tooltip = secondes simulées par seconde d'horloge
run-time = t = { $secs } s   ({ $status })
run-paused = en pause
run-running = en cours
run-diverged = divergence numérique à t = { $secs } s
run-too-stiff = trop raide pour l'intégrateur de référence à t = { $secs } s : un galet très léger ou une bande arrêtée (l'intégrateur rapier les gère), ou une charge ou une raideur si grandes qu'aucun pas ne résout les vitesses de la colonne
run-too-fast = trop rapide pour l'intégrateur rapier à t = { $secs } s : la colonne tourne à { $rate } rad/s, plus que son pas fixe ne résout ({ $most } rad par pas) ; l'intégrateur de référence la suit
run-lagging = tourne à { $achieved }x : cet ordinateur ne tient pas { $asked }x

## The status card

card-stable =
    .meaning = stable : une petite poussée reste petite (elle s'amortit ou, sans aucun amortissement, garde sa taille)
card-flutter =
    .meaning = flottement : la colonne oscille d'un côté à l'autre, de plus en plus fort (une paire de valeurs propres à droite de l'axe)
card-divergence =
    .meaning = divergence : la colonne fléchit d'un côté sans osciller (une valeur propre réelle à droite de l'axe)
card-weak-flutter = flottement faible
    .meaning = flottement faible : l'oscillation croît, mais de moins de 1 % de sa fréquence : lentement, sur de nombreuses oscillations
card-hidden = stable ou non ?
    .why = Le verdict est caché jusqu'à ce que la leçon le révèle : regardez la colonne.
card-no-figures = pas de données de stabilité : { $why }
card-growth = taux de croissance  { $rate } 1/s
    .tooltip = taux de croissance : la vitesse à laquelle le mouvement croît (positif) ou s'amortit (négatif), par seconde : la partie réelle de la valeur propre la plus à droite
card-growth-zero = taux de croissance  0 (à { $tolerance } 1/s près)
card-not-resolved = non résolu pour ces paramètres : voir l'avertissement sous la charge
card-e-folding = temps de croissance e  { $time }
    .tooltip = temps de croissance e : le temps en lequel l'oscillation croît d'un facteur e = 2.72 (1 / taux de croissance)
card-decay = temps d'amortissement  { $time }
    .tooltip = temps d'amortissement : le temps en lequel l'oscillation diminue d'un facteur e = 2.72
card-neutral = neutre : ni croissance ni amortissement
card-mode = mode { $k } sur { $n }
card-the-mode = le mode
card-frequency = fréquence  { $frequency } rad/s  (période { $period } s{ $which })
    .tooltip = fréquence : la vitesse à laquelle la colonne oscille, en radians par seconde (la hauteur de la valeur propre) ; la période est une oscillation complète. Une colonne de n barres a n modes d'oscillation, comptés ici depuis le plus lent ; la carte décrit celui qui croît le plus vite (ou s'amortit le plus lentement), et la mesure de la simulation est donnée pour ce même mode
card-non-oscillatory = non oscillant : la valeur propre dominante est réelle
card-measured = mesuré sur la simulation{ $mode }  { $measurement }
    .tooltip = la valeur propre ajustée au mouvement de la simulation elle-même (un faisceau de matrices des angles) : au moins 20 s de petites oscillations (sous 0.05 rad) depuis la dernière poussée, le dernier lâcher ou changement, chaque mode dès que la simulation en contient une période entière ; « mode 2 sur 2 » compte les modes d'oscillation de la colonne depuis le plus lent. Le ± est l'incertitude propre de l'ajustement : l'écart entre les ajustements sur les trois premiers et les trois derniers quarts de la simulation et celui sur toute la simulation. Le pas de temps dt de l'intégrateur écarte aussi la simulation du modèle linéaire, sa fréquence d'environ ω³dt²/24
card-measured-other-mode = mesuré sur la simulation : seulement { $mode }, { $measurement } ({ $card } de la carte trop faible dans cette simulation pour l'ajuster)
card-measured-other = mesuré sur la simulation : seulement une autre valeur propre, { $measurement } (celle de la carte trop faible dans cette simulation pour l'ajuster)
card-measured-after = mesuré : après 20 s de mouvement de faible amplitude (|φ| < 0.05 rad)
card-measured-two-rods = mesuré : pour deux barres seulement (les nombreux modes lents d'une chaîne demandent une simulation plus longue qu'un ajustement ne peut utiliser)
card-measurement = croissance { $growth } 1/s, fréquence { $frequency } rad/s
card-measurement-unknown = croissance { $growth } 1/s, fréquence { $frequency } rad/s (incertitude inconnue : trop peu de périodes dans la simulation)
card-grows-slowly = croît de { $percent } par période : regarder pendant des minutes, pas des secondes
card-grows-too-slowly = croît de { $percent } par période : trop lent pour être vu pendant une leçon
onset-soft = apparition douce à p = { $at } : l'oscillation se stabilise sur un cycle limite qui croît depuis zéro
onset-soft-roller = apparition douce à p = { $at } : un cycle croît depuis zéro, jusqu'à ce que le galet approche de l'adhérence
onset-hard = apparition brutale à p = { $at } : l'oscillation saute sur un grand cycle, qui persiste sous le seuil
onset-degenerate = apparition à p = { $at } ni douce ni brutale au premier ordre
onset-reversible = pas d'amortissement : aucun cycle limite sur lequel se stabiliser (une colonne réversible)
    .tooltip = Sans amortissement la colonne est réversible : le flottement commence où deux paires de valeurs propres se rencontrent sur l'axe imaginaire, et il n'y a pas d'attracteur, donc aucun cycle limite sur lequel l'oscillation pourrait se stabiliser.
onset =
    .tooltip = Douce : après le seuil l'oscillation croît depuis zéro jusqu'à un petit cycle stationnaire, plus grand quand la charge augmente ; brutale : elle saute sur un grand cycle, qui reste quand la charge baisse un peu. Adhérence : le galet cesse de glisser sur la bande, où le frottement change de loi.{"\u000A"}{"\u000A"}Premier coefficient de Liapounov { $lyapunov } au seuil p = { $at } (point de Hopf, fréquence { $frequency } rad/s).{ $amplitude }{ $sticking }
onset-amplitude = Près de lui, |phi1| du cycle vaut environ { $a } sqrt(p - { $at }) rad.
onset-sticking = Sur le galet, le glissement au contact diminue à mesure que le cycle croît ; là où il approche de zéro, le frottement n'est plus régulier et le mouvement devient du stick-slip, que cette analyse ne suit pas : la branche de l'onglet postcritique s'arrête là.

## The load ramp

ramp = rampe de charge
ramp-from = de
    .name = rampe depuis
    .tooltip = la charge où commence la rampe
ramp-to = à
    .name = rampe jusqu'à
    .tooltip = la charge où s'arrête la rampe
ramp-rate = au rythme de
    .name = rythme de la rampe
    .tooltip = la vitesse à laquelle la charge varie, par seconde simulée
ramp-start = lancer la rampe
    .tooltip = la charge va à « de » puis à « à » au rythme donné, pendant que la simulation continue (régler la charge à la main l'arrête)
ramp-pause = suspendre la rampe
    .tooltip = garder la charge où elle est ; la simulation continue
ramp-resume = reprendre
ramp-stop = arrêter
    .tooltip = terminer la rampe
ramp-done = terminée
ramp-paused = suspendue
ramp-moving = en cours
ramp-progress = p = { $load } vers { $to } à { $rate }/s ({ $doing })

## Sharing the settings

share-copy = copier les réglages
    .tooltip = le modèle, la charge, l'intégrateur et la vitesse en texte, dans le presse-papiers et la zone ci-dessous
share-paste = coller du presse-papiers
    .tooltip = prendre un texte de réglages copié ailleurs (la zone ci-dessous le montre)
share-box = ou saisir ou coller ici un texte de réglages
share-take = prendre le texte ci-dessus
    .tooltip = charger les réglages écrits dans la zone
paste-too-long = collage refusé, rien n'a changé : le texte fait { $bytes } octets ; aucun champ ici n'en prend plus de { $most } (un texte de réglages fait moins de 2000)
paste-no-text = coller les réglages : le presse-papiers ne contient pas de texte (copiez d'abord le texte des réglages)

## Lessons

lessons = leçons
lessons-built-in = la leçon intégrée { $name }
lesson-file = fichier de leçon
    .hint = un fichier de leçon (.ron)
    .tooltip = le chemin de votre propre fichier de leçon (le format est dans le README)
lesson-open = ouvrir
    .tooltip = lire et vérifier le fichier, puis le lancer
lesson-reading = lecture de { $path }
lesson-reading-stopped = { $path } : la lecture s'est arrêtée sans réponse
lesson-step = étape { $k } sur { $n }
lesson-prediction = votre prédiction : p = { $load }
lesson-predicted-load = charge prévue
    .tooltip = là où vous l'attendez ; la barre de charge la marque (touches comme sur la barre de charge : gauche, droite, maj pour dix pas, début, fin)
lesson-back = retour
    .tooltip = l'étape précédente (Page précédente)
lesson-next = suivant
    .tooltip = l'étape suivante : elle règle et lance ce qu'elle dit (Page suivante, comme l'envoie la télécommande d'un présentateur)
lesson-close = fermer la leçon
    .tooltip = quitter la leçon ; le modèle reste tel quel
lesson-next-lesson = leçon suivante : { $title }
    .tooltip = ouvrir la leçon suivante, « { $title } », à sa première étape (Page suivante)
lesson-last = la dernière étape de la dernière leçon

## The plots: axes, legends and their words for a screen reader

axis-re = Re λ (1/s)
axis-im = Im λ (rad/s)
axis-load = p = P l/k
axis-load-named = charge p = P l/k
axis-largest-angle = plus grand |φ_i| sur un cycle (rad)
axis-damping-level = amortissement g2 = c2 / √(k m l²)
axis-mass-ratio = rapport de masses m1 / (masse au-delà de l'articulation A)
axis-log-scale = { $axis } (échelle logarithmique)
axis-first-critical-load = première charge critique p
mark-load = charge
locus-far-left = { $name } : des valeurs propres jusqu'à Re λ = { $re } 1/s (modes vite amortis) sont à gauche de la vue, qui montre celles qui décident de la stabilité
legend-branch-colour = couleur des branches : la charge, p = { $from } à { $to }
legend-eigenvalues-now = valeurs propres à la charge actuelle
legend-measured = mesurées sur la simulation
legend-current-load = charge actuelle
legend-overlay-no-change = aucun changement de stabilité jusqu'au bout du curseur
legend-overlay = comparaison { $name } : { $loads }
legend-transition = p = { $load } : de { $from } à { $to }
legend-more-loads = { $count ->
    [one] { $count } autre charge critique (zieglerlab critical les liste)
   *[other] { $count } autres charges critiques (zieglerlab critical les liste)
}
legend-no-analysis = pas d'analyse
legend-stronger = plus intense : croissance ou amortissement plus rapide (maximum : { $largest } 1/s)
legend-critical-loads = charges critiques
legend-now = maintenant
legend-now-off = maintenant : hors de la carte ({ $why })
legend-now-no-value = maintenant : pas sur la carte ({ $axis } n'a pas de valeur pour cette colonne)
legend-now-below = { $name } = { $value } est sous { $bound }
legend-now-above = { $name } = { $value } est au-dessus de { $bound }
legend-this-model = ce modèle : p = { $load }
legend-straight-stable = colonne droite, stable
legend-straight-unstable = colonne droite, instable
legend-stable-cycle = cycle limite stable
legend-unstable-cycle = cycle limite instable
legend-hopf-point = début du flottement (point de Hopf)
legend-cycle-fold = LPC : pli des cycles
legend-cycle-period-doubling = PD : doublement de période
legend-cycle-torus = NS : tore (Neimark-Sacker)
legend-cycle-symmetry-breaking = BPC : brisure de symétrie (point de branchement des cycles)
legend-sweep-up = balayage montant (une simulation)
legend-sweep-down = balayage descendant (une simulation)
legend-seen-in-ramp = vu pendant la rampe
legend-largest-angle = plus grand angle de cette simulation, dernière période
legend-flutter-soft = début du flottement, doux : une petite oscillation croît
legend-flutter-hard = début du flottement, brutal : saut vers une grande oscillation
legend-divergence-onset = début de la divergence
legend-special-points = B : Bautin (de doux à brutal), BT : Bogdanov-Takens, DH : double Hopf, ZH : zéro-Hopf
legend-fold-of-cycles = pli des cycles : en dessous aucune oscillation ne survit
legend-hysteresis = hystérésis : repos et grande oscillation tous deux stables
describe-against = { $y } en fonction de { $x }
describe-range = { $state } de { $from } à { $to }
describe-ranges = intervalles : { $ranges }
describe-mark = { $name } à { $x }
describe-marked = repères : { $marks }
describe-point = { $name } en ({ $x } ; { $y })
describe-points = points nommés : { $points }
describe-bands = teintée entre un pli des cycles et un début brutal du flottement : la bande d'hystérésis, où repos et grande oscillation sont tous deux stables
describe-curves = { $count ->
    [one] { $count } courbe
   *[other] { $count } courbes
}
describe-now-stable = à la charge actuelle les { $count } valeurs propres sont à gauche de l'axe imaginaire : une poussée s'amortit
describe-now-flutter = à la charge actuelle { $right } des { $count } valeurs propres sont à droite de l'axe imaginaire, dont { $oscillating } hors de l'axe réel : une oscillation croît (flottement)
describe-now-divergence = à la charge actuelle { $right } des { $count } valeurs propres sont à droite de l'axe imaginaire, aucune hors de l'axe réel : la colonne fléchit (divergence)
describe-map = une carte de { $columns } sur { $rows } cellules : stable { $stable } %, flottement { $flutter } %, divergence { $divergence } %

## The scene, the load bar and the tabs' own words

scene-name = la colonne
scene-swing = son oscillation maintenant { $rad } rad
scene-hidden = la colonne, { $swing }
scene-analysing = la colonne, { $swing } ; sa stabilité est en cours d'analyse
scene-stable = stable : une poussée s'amortit, jusqu'au centième en { $secs } s ; { $swing }
scene-undamped = stable mais non amortie : une poussée continue d'osciller, sans croître ni s'amortir ; { $swing }
scene-flutter = la colonne flotte : une oscillation croît, doublant toutes les { $secs } s à { $frequency } rad/s ; { $swing }
scene-divergence = divergence : la colonne fléchit hors de la droite, doublant toutes les { $secs } s ; { $swing }
scene-stopped = la simulation s'est arrêtée : { $status } ; R en lance une nouvelle
scene-drag-hint = faire glisser l'extrémité ou une articulation pour déplacer la colonne
scene-whole-reach = portée entière
    .tooltip = cadrer tout le disque que l'extrémité peut atteindre, fixe ; désactivé, la vue suit le mouvement, s'éloigne dès que la colonne oscille fort et se rapproche quand elle se calme, toujours avec l'encastrement en vue
scene-delta =
    .tooltip = δ : l'angle entre la direction de la dernière barre (la flèche en tirets, où pointerait une force suiveuse idéale) et la force qu'applique réellement le frottement de la bande (la flèche pleine), tracé comme l'arc à l'extrémité. δ = 0 est une suiveuse parfaite ; le galet tourne la force de δ en glissant de côté sur la bande (éq. 23)
scene-stick-slip = stick-slip : la vitesse de glissement est sous 1e-4 m/s ; le frottement de Coulomb est ici régularisé, hors du domaine de validité du modèle
scene-band = bande se déplaçant vers la gauche à V = { $speed } m/s
load-bar = charge{"\u000A"}p = { $load }
    .name = curseur de charge
    .tooltip = la charge p = P l/k : cliquer ou faire glisser ici, ou utiliser les flèches (barre ciblée : gauche et droite, maj pour dix pas, début et fin)
load-bar-said = charge p = { $load } de 0 à { $end }
load-bar-said-hidden = { $load } : l'état est caché jusqu'à ce que la leçon le révèle
load-bar-said-analysing = { $load } : analyse en cours
load-bar-said-range = { $load } : { $state }, de p = { $from } à { $to }
load-bar-said-beyond = { $load } : au-delà de l'intervalle analysé
view-hint = glisser : déplacer · Ctrl+molette : zoomer · double-clic : ajuster
    .more = Montrer à nouveau toutes les données (comme un double-clic sur un graphique).{"\u000A"}Glisser ou faire défiler pour déplacer, Ctrl+molette pour zoomer, tracer un cadre avec le bouton droit pour zoomer dessus.
view-fit = ajuster
map-readout-growth = taux de croissance { $rate } 1/s
map-kick-settles = une poussée s'amortit
map-kick-hysteresis = une petite poussée s'amortit, une grande le laisse osciller (hystérésis)
map-kick-grows-softly = une poussée croît doucement jusqu'à une petite oscillation
map-kick-jumps = une poussée saute à une grande oscillation
map-following = suivi de la frontière du flottement et des plis des cycles…
map-not-followed = frontières non suivies : { $why }
map-readout-hint = pointer la carte pour lire une cellule ; cliquer pour prendre sa charge et son paramètre
histories-delta = δ : l'angle de la force de la bande par rapport à la barre 2
histories-energy = énergie cinétique + élastique
histories-band-power = puissance venant de la bande
histories-rod-2 = barre 2
zoom-outside = le zoom { $zoom } est hors de { $least } à { $most } : ramené à { $held } (Ctrl+0 : 100 %)
plot-name = graphique : { $y } en fonction de { $x }

## The tabs' controls and captions, and the record menu

locus-computing = Calcul du lieu des racines de ces paramètres...
locus-none = Pas de lieu des racines pour ces paramètres.
locus-none-why = Pas de lieu des racines pour ces paramètres : { $why }.
locus-title = lieu des racines, p = { $from } à { $to }
map-rows = lignes { $done } sur { $total }
map-grey-rows = les lignes grises n'ont pas d'analyse : { $why }
map-empty-range = la plage de la carte de { $lo } à { $hi } est vide
map-no-thread = pas de fil d'exécution pour la carte : { $why }
map-stopped = la carte s'est arrêtée : { $why }
map-axis = charge p en fonction de
    .tooltip = le second paramètre de la carte (son intervalle ci-dessous relance la carte)
map-from = de
    .name = intervalle de la carte depuis
    .tooltip = où commence le second paramètre
map-to = à
    .name = intervalle de la carte jusqu'à
    .tooltip = où finit le second paramètre
paradox-computing = calcul des charges de flottement quand l'amortissement disparaît ...
paradox-joints = La charge de flottement avec des amortisseurs aux articulations c1 = (c1/c2) c2 quand le niveau d'amortissement g2 = c2 / sqrt(k m l^2) tend vers zéro : la limite dépend du rapport et se trouve sous la charge sans amortissement (paradoxe de Ziegler).
paradox-external = La charge de flottement avec des amortisseurs égaux aux articulations c1 = c2 = c (amortissement interne) et une traînée c_ext = (c_ext l^3 / c) c / l^3 le long des barres (amortissement externe) quand le niveau g2 = c / sqrt(k m l^2) tend vers zéro : l'amortissement externe déstabilise aussi, et la limite dépend du rapport.
paradox-no-extent = les courbes n'ont pas d'étendue selon le rapport
paradox-no-thread = pas de fil d'exécution pour les courbes : { $why }
paradox-dead-load = Une charge morte (eta = 0) est conservative : elle ne flotte jamais, donc il n'y a pas de paradoxe à montrer.
paradox-stable-throughout = Pas de courbe à tracer : à chaque rapport montré la colonne reste stable jusqu'à p = { $end }.
paradox-failed = Pas de courbe à tracer : { $why }.
paradox-kind = amortissement qui disparaît :
paradox-kind-joints = amortisseurs aux articulations
    .tooltip = les amortisseurs aux articulations c1 et c2 dans le rapport c1/c2
paradox-kind-external = traînée externe et interne
    .tooltip = traînée c_ext le long des barres (externe) et amortisseurs égaux aux articulations c1 = c2 = c (interne) dans le rapport c_ext l^3 / c
paradox-roller = La charge à laquelle la colonne à galet perd d'abord sa stabilité, en fonction de la masse du galet, pour trois vitesses de bande (l'amortissement par glissement est mu R / V).
paradox-roller-falling = en baisse vers zéro quand nu -> 0
paradox-roller-flat = sans baisse vers zéro sur cet intervalle
paradox-roller-massless = ; le galet sans masse (la suiveuse idéale) perd sa stabilité à p = { $load }
paradox-roller-caption = { $intro } À la plus petite masse montrée, nu = { $nu }, les courbes sont à { $at }, { $trend }{ $massless }.
record-next = les prochaines
record-secs = s dans
    .name = secondes à enregistrer
    .tooltip = secondes de la fenêtre à enregistrer (de 1 à 60)
record-folder =
    .name = dossier de l'enregistrement
    .tooltip = le dossier où va le GIF
record-choosing = choix en cours...
record-choose = choisir...
    .tooltip = choisir le dossier dans la boîte de dialogue du bureau
    .title = zieglerlab : le dossier des enregistrements
record-start = enregistrer
    .tooltip = enregistrer ce que montre la fenêtre, 10 images par seconde, dans un GIF
    .no-folder = le dossier n'existe pas

## A lesson's revealed results

reveal-never = la colonne ne perd pas sa stabilité jusqu'à p = { $load }
reveal-theory = la théorie : instable dès p = { $load }
reveal-seen = ; le mouvement est apparu à p = { $load }
reveal-predicted = Vous aviez prédit p = { $load } ;{" "}
reveal-first-instability = { $predicted }{ $theory }{ $seen }.
reveal-right = Exact : vous avez choisi « { $chosen } », la réponse.
reveal-wrong = Pas celle-ci : vous avez choisi « { $chosen } » ; la réponse est « { $answer } ».
reveal-answer = La réponse : « { $answer } ».
reveal-no-answer = la théorie n'a pas de réponse à cette charge
reveal-period = , une période de { $secs } s
reveal-flutter = flottement : l'oscillation double toutes les { $secs } s{ $period }
reveal-divergence = divergence : l'inclinaison double toutes les { $secs } s
reveal-stable = stable : une poussée diminue de moitié toutes les { $secs } s{ $period }
reveal-undamped = stable : une poussée ne croît ni ne s'amortit{ $period }
reveal-here = La théorie à p = { $load } : { $how }.

## Messages in the status line, the recording and the typed save

notice-rods-load-moved = barres = { $rods } : la barre de charge va maintenant de 0 à { $end }, et la charge s'est déplacée avec elle de p = { $from } à { $to } (le même endroit de la barre ; saisir la charge pour en choisir une autre)
notice-rods-load-kept = barres = { $rods } : la charge p = { $load } est gardée ({ $why })
notice-switched-to-reference = la colonne est trop raide pour l'intégrateur rapier à son pas de 1/240 s (amortissement ou raideur énormes pour peu de masse) ; passage à l'intégrateur de référence
notice-lesson-last-step = c'était la dernière étape de la leçon : fermez-la, ou ouvrez-en une autre depuis le menu leçons
notice-paste-nothing = rien à coller : copiez d'abord un texte de réglages (« copier les réglages » dans le menu partager), ou saisissez-le dans la zone
notice-paste-not-understood = réglages collés refusés, rien n'a changé : { $what } non compris
notice-pasted = réglages collés
notice-not-saved = non enregistré : aucun fichier choisi (là où aucune boîte de dialogue ne s'est ouverte, ce bureau n'en offre pas)
recording-saved = enregistrement sauvé dans { $path } : { $frames } images en { $secs } s{ $slow }
recording-jerky = ; il n'a saisi que { $caught } images par seconde sur les { $fps } par seconde du GIF (le rythme de capture : la machine était trop occupée pour en prendre plus), donc le GIF passe à la bonne vitesse mais par saccades : une fenêtre plus petite (ou le mode projecteur désactivé) en enregistre plus
recording-title = { $title } : enregistrement, encore { $secs } s
recording-making = création du GIF : image { $done } sur { $kept }
save-as = enregistrer sous
    .path = chemin d'enregistrement
save-as-typed = Aucune boîte de dialogue de fichiers ne s'est ouverte sur ce bureau : saisissez où enregistrer { $what }.
save-as-exists = { $path } existe : le remplacer ? (enregistrer à nouveau pour remplacer)
save-as-replace = remplacer
save-as-save = enregistrer
save-as-cancel = annuler
save-as-what-table = le tableau (CSV)
save-as-what-plots = les graphiques (PNG)
save-as-no-path = saisir le chemin d'un fichier
save-as-no-folder = son dossier n'existe pas
save-as-folder = c'est un dossier : saisir le nom d'un fichier dedans
save-as-pipe = c'est un tube ou un périphérique, pas un fichier : saisir le chemin d'un fichier
save-as-protected = le fichier existe et ne peut pas être écrit ({ $why }) ; il reste tel quel

## The paradox curves

paradox-ratio-joints = c1/c2
paradox-ratio-external = c_ext l^3 / c (externe / interne)
paradox-ratio-roller-mass = nu = m3/m
paradox-curve-damping = amortissement g2 = { $level }
paradox-curve-speed = V = { $speed } m/s
paradox-curve-all-speeds = { $speeds } : une courbe, la première charge critique ne dépend pas de V
paradox-reference-undamped = sans amortissement
paradox-reference-massless = nu = 0 : la suiveuse idéale
paradox-reference = { $name } : p = { $load }
paradox-reference-above = { $name } : p = { $load } (au-dessus de l'axe)

## Refused values and the engine's failures

refused-value = { $subject } = { $value } : { $allowed }
refused-not-a-number = « { $text } » n'est pas un nombre
refused-unknown-preset = préréglage inconnu « { $name } » ; les préréglages sont : { $known }
refused-unknown-key = clé inconnue « { $key } » ; les clés sont : { $known }
refused-malformed = « { $text } » n'est pas clé=valeur avec un nombre (p. ex. load=2.5) : { $reason }
refused-conflict = { $first } et { $second } fixent la même grandeur ; n'en donner qu'une
allowed-finite = doit être un nombre fini
allowed-positive = doit être > 0
allowed-non-negative = doit être >= 0
allowed-key-range = doit être un nombre fini { $range } { $unit }
allowed-key-count = doit être un nombre entier { $range }
allowed-between = doit être compris entre { $min } et { $key } = { $max }
allowed-rods = doit être un nombre entier de 2 à { $most }
allowed-eta-range = doit être compris entre 0 (charge morte) et 1 (force suiveuse)
allowed-frictionless-band = doit être > 0 : sans frottement la bande n'exerce aucune charge (pour une colonne non chargée, mettre la charge à 0)
allowed-friction-too-small = trop petit : la charge p = { $load } exigerait une force normale R = P / mu au-delà de tout nombre
allowed-beyond-analysis = au-delà de ce que l'analyse peut élever au carré (grandeurs de { $smallest } à { $largest })
allowed-makes-beyond-analysis = porte { $what } au-delà de ce que l'analyse peut élever au carré (grandeurs de { $smallest } à { $largest })
allowed-masses-too-unequal = les masses sont trop inégales : le déterminant de la matrice de masse est sous 1e-12 de son échelle, donc l'arrondi décide du mouvement (p. ex. une masse en tête ou un galet de plus d'environ 1e12 fois celle des barres)
allowed-mass-missing = la colonne a besoin de masse au-delà de l'articulation A (barre 2, tête ou galet) et d'une masse ou inertie qui se meut avec la seule barre 1 ; la matrice de masse est singulière
allowed-chain-massless = une chaîne a besoin de masse ou d'inertie sur chaque copie de la barre 2 (m2 ou I2 > 0) : avec une barre 2 sans masse, la matrice de masse de la chaîne est singulière
allowed-needs-damped-joint2 = exige une articulation 2 amortie : fixer d'abord c2 > 0 (ou le niveau d'amortissement)
allowed-infinite-damper-ratio = c2 = 0 avec c1 > 0 : le rapport c1/c2 à garder est infini ; fixer d'abord c2 > 0
allowed-band-at-rest = doit être > 0 pour l'analyse linéaire : à V = 0 le frottement de Coulomb n'est pas dérivable autour du repos (stick-slip)
allowed-roller-has-no-eta = le galet n'a pas d'eta : le frottement de la bande donne la direction de la force, contre le glissement au contact, et son angle delta avec la barre 2 est un résultat du mouvement, pas un paramètre
allowed-state-length = doit valoir 2 (barres + 1) : les angles, la rotation et leurs vitesses
allowed-time-step = doit être un pas de temps dans (0, 1] s
quantity-load-force = la charge P
quantity-load-p = la charge p = P l/k
quantity-inertia-o = l'inertie autour de O
quantity-inertia-coupling = l'inertie de couplage
quantity-inertia-a = l'inertie autour de A
quantity-stiffness-k1 = la raideur k1
quantity-stiffness-k2 = la raideur k2
quantity-damper-c1 = l'amortisseur c1
quantity-damper-c2 = l'amortisseur c2
quantity-drag = la traînée c_ext l^3
quantity-slip-damping = l'amortissement de glissement mu R l^2 / V
quantity-spin-inertia = l'inertie de rotation du galet m3 r^2 / 2
quantity-mass-matrix = la matrice de masse
quantity-damper-ratio = c1/c2
quantity-damping-level = damping
quantity-mass-ratio = mass_ratio
quantity-drag-ratio = c_ext l^3/c
quantity-state-length = la longueur de l'état
quantity-time-step = dt
engine-too-stiff = le moteur rapier ne peut pas intégrer cette colonne à dt = { $step } s : ses ressorts et amortisseurs atteignent des taux de { $rate } 1/s, qui exigent dt < { $need } s ; utiliser le moteur de référence
engine-rapier-world = le monde rapier2d n'a pas pu être construit pour cette colonne (ses articulations ont été refusées) ; utiliser le moteur de référence
analysis-not-converged = l'itération des valeurs propres n'a pas convergé à la charge p = { $load }
ramp-refused-end = { $end } = { $value } : doit être une charge p >= 0
ramp-refused-rate = vitesse de la rampe = { $value } : doit être une charge positive par seconde
ramp-refused-too-slow = vitesse de la rampe = { $value } : doit valoir au moins { $slowest } de charge par seconde (plus lente, la charge ne bougerait pas visiblement pendant des jours)
ramp-refused-too-long = la rampe de { $from } à { $to } à { $rate } par seconde prend { $secs } s de temps simulé ; au plus { $most } s (environ quatre mois) : une vitesse plus grande ou des bornes plus proches
ramp-refused-model = { $end } = { $value } : { $why }

## Messages that frame another's (a file system's, a thread's) words

notice-ramp-refused = rampe : { $why }
notice-ramp-stopped = rampe arrêtée : { $why }
notice-map-point-refused = carte : { $why }
notice-overlay-unavailable = superposition indisponible : { $why }
notice-table-not-saved = non enregistré : { $why }
notice-no-locus = il n'y a pas de lieu des racines pour ces paramètres
notice-no-thread = non enregistré : pas de fil d'exécution pour écrire ({ $why })
notice-saved-lines = { $count ->
    [one] { $count } ligne enregistrée
   *[other] { $count } lignes enregistrées
} dans { $path }
notice-write-failed = non enregistré : { $why }
notice-plots-saved = graphiques enregistrés dans { $path }
notice-plots-not-saved = graphiques non enregistrés : { $why }
notice-recording-failed = l'enregistrement a échoué : { $why }
notice-layout-not-saved = disposition de la fenêtre non enregistrée : { $why }
notice-stored-overlay = la superposition enregistrée { $name } n'est pas un préréglage ; pas de superposition
notice-stored-map-axis = l'axe de carte enregistré n'est pas utilisé : { $why }
notice-stored-language = la langue enregistrée n'est pas utilisée : { $why }
notice-lesson-refused = leçon { $name } : { $why }
notice-lesson-not-opened = leçon non ouverte : { $why }
notice-reset-closed-lesson = tout réinitialisé : la leçon « { $title } » est fermée (la rouvrir depuis le menu des leçons)

## The post-critical tab's notes

cycles-computing = suivi des cycles limites depuis chaque début du flottement ...
cycles-none = pas de cycle limite : { $why }
cycles-no-onset = aucun début du flottement dans la plage de la barre de charge : pas de cycle limite
cycles-chain-too-long = une chaîne de { $rods } barres est trop longue à suivre dans la fenêtre (16 barres prennent environ 20 s sur deux cœurs, et le travail croît plus vite que le nombre de barres) ; `zieglerlab bifurcation` calcule ses cycles en ligne de commande
cycles-no-thread = pas de fil d'exécution pour les cycles : { $why }
cycles-branch = { $name } : apparition { $onset } à p = { $at } ; la branche s'est arrêtée : { $end }
cycles-offshoot = { $name } : cycles asymétriques (et leurs images miroir) depuis le BPC à p = { $at } ; la branche s'est arrêtée : { $end }
cycles-onset-soft = douce
cycles-onset-hard = brutale
cycles-no-branch = début du flottement à p = { $at } : { $why }
cycles-no-branch-reversible = pas d'amortissement, une colonne réversible : aucun cycle limite à suivre
cycles-no-branch-degenerate = le premier coefficient de Liapounov est nul à sa précision près ; cycles non suivis
cycles-no-branch-not-converged = la méthode de tir n'a pas convergé près de l'apparition ; pas de cycle
cycles-end-left-range = a quitté la plage de charges
cycles-end-large-amplitude = l'amplitude d'un angle a dépassé { $most } rad (la colonne fait le tour)
cycles-end-long-period = la période a dépassé { $most } fois celle de l'apparition
cycles-end-lost = la méthode de tir n'a pas convergé au-delà de p = { $load }
cycles-end-stick-slip = le contact du galet approche l'adhérence sur la bande au-delà de p = { $load } (stick-slip : le frottement n'y est pas lisse)
cycles-end-unresolved = les cycles au-delà de p = { $load } ne sont pas résolus (multiplicateur trivial écarté de 1 de plus de { $tolerance })
cycles-end-point-limit = { $most } cycles calculés
cycles-end-cancelled = arrêté sur demande

## Why the stability along the locus is not resolved (shown on hover)

not-resolved-mode-span = la stabilité n'est pas résolue : à p = { $load } les modes vont de { $fastest } 1/s à { $slowest } 1/s, un rapport au-delà de { $span }, donc les taux de croissance des modes lents sont laissés à l'arrondi (un mode bien plus rapide que les autres, comme la rotation d'un galet de masse nu infime)
not-resolved-slow-mode-lost = la stabilité n'est pas résolue : à p = { $load } les modes vont de { $scale } 1/s à { $slowest } 1/s, donc les taux de croissance sous { $tolerance } 1/s se perdent dans l'arrondi (le modèle est proche d'une limite singulière : une bande V très lente ou un très grand amortissement)
not-resolved-methods-disagree = la stabilité n'est pas résolue : à p = { $load } les racines suivies et la décomposition de Schur divergent sur l'état (l'arrondi en décide : un mode bien plus rapide que les autres, comme la rotation d'un galet de masse nu infime) ; les charges critiques montrées peuvent être fausses ou manquer
not-resolved-rounding-decides = la stabilité n'est pas résolue : pour p de { $low } à { $high } les taux de croissance sont entre 1e-12 et 1e-10 de l'échelle des fréquences, où l'arrondi décide de l'état (un galet de masse nu infime, dont le faible flottement croît en proportion de nu, ou une bande V très lente) ; les charges critiques montrées peuvent être déplacées ou manquer
not-resolved-refinement-cut = le lieu des racines n'a été affiné que jusqu'à p = { $load } : au-delà, les branches ne sont échantillonnées qu'aux charges régulièrement espacées, donc une fenêtre d'un autre état plus étroite que leur espacement peut manquer (la limite de temps et de mémoire de l'affinage a été atteinte)

## The stored state's check before the window opens (a damaged store)

store-zoom = le facteur de zoom { $zoom } (permis de 0.2 à 5)
store-geometry = la géométrie de fenêtre { $width } x { $height } points à l'échelle { $scale }
store-unreadable = l'état enregistré n'a pas pu être lu ({ $why }) ; une copie est gardée dans { $copy } ; démarrage avec les valeurs par défaut
store-unreadable-uncopied = n'a pu être ni lu ({ $why }) ni copié ({ $error })
store-moved = l'état enregistré { $path } { $why } ; il est déplacé vers { $aside } et les valeurs par défaut s'appliquent
store-not-moved = l'état enregistré { $path } { $why } et n'a pas pu être mis de côté ({ $error }) ; les réglages ne seront pas enregistrés
store-folder-not-made = les réglages ne seront pas enregistrés : le dossier { $folder } ne peut pas être créé ({ $error })
store-folder-full = les réglages ne seront pas enregistrés : le dossier { $folder } n'accepte aucun nouveau fichier ({ $error })
store-not-writable = les réglages ne seront pas enregistrés : { $path } ne peut pas être écrit ({ $error })
store-is-folder = est un dossier
store-is-device = est un périphérique, un tube ou une socket
store-too-large = contient { $bytes } octets (au plus { $most } sont lus)
store-entry = { $why } (entrée « { $key } » d'eframe)
store-ignored = état enregistré : ignoré { $what }
store-ignored-not-rewritten = état enregistré : ignoré { $what } (le fichier n'a pas pu être réécrit : { $error })
store-settings-unreadable = les réglages enregistrés n'ont pas pu être lus
store-original-kept = l'original est gardé dans { $copy }
store-original-lost = aucune copie de l'original n'a pu être gardée ({ $error })
store-settings-partly = réglages enregistrés : ignoré { $what } ; le reste est gardé
store-settings-ignored = réglages enregistrés ignorés ({ $why }) ; démarrage avec les valeurs par défaut
layout-ignored = disposition de fenêtre enregistrée ignorée ({ $why }) ; la disposition par défaut s'applique
notice-paste-unreadable = réglages collés non compris, rien n'a changé : { $why }
notice-paste-refused = réglages collés refusés, rien n'a changé : { $why }
notice-analysis-unavailable = analyse indisponible : { $why }
notice-lesson-step = étape { $step } de la leçon : { $why }
notice-lesson = leçon : { $why }
