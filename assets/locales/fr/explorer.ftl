# La fenêtre, sa barre, ses outils et ses panneaux, en français.

language-hover = La langue de la fenêtre. Elle suit celle du système sauf si elle est choisie ici.
