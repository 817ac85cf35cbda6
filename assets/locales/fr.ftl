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
