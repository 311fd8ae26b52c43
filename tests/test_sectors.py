"""Seed 000/002 sector method: every printed row of Table 1 (both seeds) and
Tables 2-4 (seed 002) reproduced to the printed digits.

The tables below are pasted literally from the seeds (decimal commas, Unicode
minus signs); a lone dash is the paper's empty cell.
"""

import math

import numpy as np
import pytest

from propulsor.errors import InputError
from propulsor.gears.sectors import (
    PINION_POINT_COLUMNS,
    RADII_COLUMNS,
    SECTOR_COLUMNS,
    WHEEL_POINT_COLUMNS,
    involute,
    pinion_tooth_points,
    sector_hub_speed,
    sector_radii,
    sector_ratio,
    sector_table,
    sector_tip_thickness,
    structured_rows,
    wheel_space_points,
)
from propulsor.laws.walking import SEED_000, SEED_002, WalkingLaw

TABLE1_SEED000 = """
1 -0,7854 -45,00 0,0756 4,33 82,20 -1,5708 -90,00 0,1013 5,81 61,30
2 -0,7098 -40,67 0,0719 4,12 86,37 -1,4695 -84,19 0,1087 6,23 57,13
3 -0,6379 -36,55 0,0692 3,97 89,76 -1,3607 -77,96 0,1156 6,62 53,74
4 -0,5687 -32,58 0,0671 3,85 92,53 -1,2451 -71,34 0,1219 6,98 50,97
5 -0,5016 -28,74 0,0655 3,75 94,80 -1,1232 -64,36 0,1276 7,31 48,70
6 -0,4360 -24,98 0,0643 3,68 96,66 -0,9957 -57,05 0,1326 7,60 46,84
7 -0,3718 -21,30 0,0633 3,63 98,16 -0,8630 -49,45 0,1370 7,85 45,34
8 -0,3085 -17,67 0,0625 3,58 99,35 -0,7260 -41,60 0,1407 8,06 44,15
9 -0,2459 -14,09 0,0620 3,55 100,27 -0,5853 -33,54 0,1437 8,23 43,23
10 -0,1840 -10,54 0,0615 3,53 100,94 -0,4416 -25,30 0,1459 8,36 42,56
11 -0,1224 -7,01 0,0613 3,51 101,37 -0,2957 -16,94 0,1475 8,45 42,13
12 -0,0612 -3,50 0,0612 3,50 101,59 -0,1482 -8,49 0,1482 8,49 41,91
13 0,0000 0,00 0,0612 3,50 101,59 0,0000 0,00 0,1482 8,49 41,91
14 0,0612 3,50 0,0613 3,51 101,37 0,1482 8,49 0,1475 8,45 42,13
15 0,1224 7,01 0,0615 3,53 100,94 0,2957 16,94 0,1459 8,36 42,56
16 0,1840 10,54 0,0620 3,55 100,27 0,4416 25,30 0,1437 8,23 43,23
17 0,2459 14,09 0,0625 3,58 99,35 0,5853 33,54 0,1407 8,06 44,15
18 0,3085 17,67 0,0633 3,63 98,16 0,7260 41,60 0,1370 7,85 45,34
19 0,3718 21,30 0,0643 3,68 96,66 0,8630 49,45 0,1326 7,60 46,84
20 0,4360 24,98 0,0655 3,75 94,80 0,9957 57,05 0,1276 7,31 48,70
21 0,5016 28,74 0,0671 3,85 92,53 1,1232 64,36 0,1219 6,98 50,97
22 0,5687 32,58 0,0692 3,97 89,76 1,2451 71,34 0,1156 6,62 53,74
23 0,6379 36,55 0,0719 4,12 86,37 1,3607 77,96 0,1087 6,23 57,13
24 0,7098 40,67 0,0756 4,33 82,20 1,4695 84,19 0,1013 5,81 61,30
"""

TABLE1_SEED002 = """
1 −0,7854 −45,00 0,0827 4,74 94,73 −3,1416 −180,00 0,2588 14,83 30,27
2 −0,7027 −40,26 0,0812 4,65 96,48 −2,8828 −165,17 0,2747 15,74 28,52
3 −0,6215 −35,61 0,0800 4,58 97,96 −2,6081 −149,43 0,2897 16,60 27,04
4 −0,5415 −31,03 0,0790 4,53 99,19 −2,3184 −132,83 0,3035 17,39 25,81
5 −0,4625 −26,50 0,0782 4,48 100,20 −2,0149 −115,44 0,3159 18,10 24,80
6 −0,3843 −22,02 0,0776 4,44 101,00 −1,6990 −97,35 0,3265 18,71 24,00
7 −0,3068 −17,58 0,0771 4,42 101,63 −1,3725 −78,64 0,3353 19,21 23,37
8 −0,2297 −13,16 0,0767 4,40 102,09 −1,0373 −59,43 0,3420 19,59 22,91
9 −0,1529 −8,76 0,0765 4,38 102,39 −0,6953 −39,84 0,3465 19,85 22,61
10 −0,0764 −4,38 0,0764 4,38 102,54 −0,3488 −19,98 0,3488 19,98 22,46
11 0,0000 0,00 0,0764 4,38 102,54 0,0000 0,00 0,3488 19,98 22,46
12 0,0764 4,38 0,0765 4,38 102,39 0,3488 19,98 0,3465 19,85 22,61
13 0,1529 8,76 0,0767 4,40 102,09 0,6953 39,84 0,3420 19,59 22,91
14 0,2297 13,16 0,0771 4,42 101,63 1,0373 59,43 0,3353 19,21 23,37
15 0,3068 17,58 0,0776 4,44 101,00 1,3725 78,64 0,3265 18,71 24,00
16 0,3843 22,02 0,0782 4,48 100,20 1,6990 97,35 0,3159 18,10 24,80
17 0,4625 26,50 0,0790 4,53 99,19 2,0149 115,44 0,3035 17,39 25,81
18 0,5415 31,03 0,0800 4,58 97,96 2,3184 132,83 0,2897 16,60 27,04
19 0,6215 35,61 0,0812 4,65 96,48 2,6081 149,43 0,2747 15,74 28,52
20 0,7027 40,26 0,0827 4,74 94,73 2,8828 165,17 0,2588 14,83 30,27
"""

TABLE2_SEED002 = """
1 –180,00 30,27 27,77 27,15 32,77 –45,00 94,73 92,23 91,60 97,23
2 –165,17 28,52 26,02 25,40 31,02 –40,26 96,48 93,98 93,35 98,98
3 –149,43 27,04 24,54 23,92 29,54 –35,61 97,96 95,46 94,83 100,46
4 –132,83 25,81 23,31 22,69 28,31 –31,03 99,19 96,69 96,06 101,69
5 –115,44 24,80 22,30 21,68 27,30 –26,50 100,20 97,70 97,07 102,70
6 –97,35 24,00 21,50 20,87 26,50 –22,02 101,00 98,50 97,88 103,50
7 –78,64 23,37 20,87 20,24 25,87 –17,58 101,63 99,13 98,51 104,13
8 –59,43 22,91 20,41 19,79 25,41 –13,16 102,09 99,59 98,96 104,59
9 –39,84 22,61 20,11 19,49 25,11 –8,76 102,39 99,89 99,26 104,89
10 –19,98 22,46 19,96 19,34 24,96 –4,38 102,54 100,04 99,41 105,04
11 0,00 22,46 19,96 19,34 24,96 0,00 102,54 100,04 99,41 105,04
12 19,98 22,61 20,11 19,49 25,11 4,38 102,39 99,89 99,26 104,89
13 39,84 22,91 20,41 19,79 25,41 8,76 102,09 99,59 98,96 104,59
14 59,43 23,37 20,87 20,24 25,87 13,16 101,63 99,13 98,51 104,13
15 78,64 24,00 21,50 20,87 26,50 17,58 101,00 98,50 97,88 103,50
16 97,35 24,80 22,30 21,68 27,30 22,02 100,20 97,70 97,07 102,70
17 115,44 25,81 23,31 22,69 28,31 26,50 99,19 96,69 96,06 101,69
18 132,83 27,04 24,54 23,92 29,54 31,03 97,96 95,46 94,83 100,46
19 149,43 28,52 26,02 25,40 31,02 35,61 96,48 93,98 93,35 98,98
20 165,17 30,27 27,77 27,15 32,77 40,26 94,73 92,23 91,60 97,23
"""

TABLE3_SEED002 = """
1 1 0,0000 0,00 0,0000 0,00 −3,0999 −177,61 −2,9244 −167,56 27,77
1 2 0,2946 16,88 0,0088 0,51 −3,0911 −177,11 −2,9333 −168,06 29,02
1 3 0,4093 23,45 0,0245 1,40 −3,0755 −176,21 −2,9489 −168,96 30,27
1 4 0,4927 28,23 0,0442 2,53 −3,0558 −175,08 −2,9686 −170,09 31,52
1 5 0,5597 32,07 0,0668 3,83 −3,0331 −173,79 −2,9913 −171,39 32,77
2 1 0,0000 0,00 0,0000 0,00 −2,8395 −162,69 −2,6514 −151,91 26,02
2 2 0,3039 17,41 0,0097 0,56 −2,8298 −162,14 −2,6611 −152,47 27,27
2 3 0,4218 24,17 0,0269 1,54 −2,8126 −161,15 −2,6783 −153,46 28,52
2 4 0,5073 29,07 0,0485 2,78 −2,7910 −159,91 −2,6999 −154,69 29,77
2 5 0,5757 32,98 0,0733 4,20 −2,7662 −158,49 −2,7247 −156,11 31,02
3 1 0,0000 0,00 0,0000 0,00 −2,5634 −146,87 −2,3631 −135,40 24,54
3 2 0,3126 17,91 0,0106 0,61 −2,5528 −146,26 −2,3737 −136,00 25,79
3 3 0,4334 24,83 0,0293 1,68 −2,5340 −145,19 −2,3924 −137,08 27,04
3 4 0,5207 29,84 0,0528 3,03 −2,5106 −143,85 −2,4159 −138,42 28,29
3 5 0,5903 33,82 0,0797 4,57 −2,4837 −142,30 −2,4428 −139,96 29,54
4 1 0,0000 0,00 0,0000 0,00 −2,2724 −130,20 −2,0609 −118,08 23,31
4 2 0,3204 18,36 0,0114 0,66 −2,2610 −129,54 −2,0723 −118,73 24,56
4 3 0,4437 25,42 0,0316 1,81 −2,2408 −128,39 −2,0925 −119,89 25,81
4 4 0,5327 30,52 0,0569 3,26 −2,2156 −126,94 −2,1177 −121,34 27,06
4 5 0,6034 34,57 0,0857 4,91 −2,1867 −125,29 −2,1466 −122,99 28,31
5 1 0,0000 0,00 0,0000 0,00 −1,9678 −112,75 −1,7461 −100,04 22,30
5 2 0,3272 18,75 0,0122 0,70 −1,9556 −112,05 −1,7583 −100,74 23,55
5 3 0,4528 25,95 0,0337 1,93 −1,9341 −110,82 −1,7798 −101,97 24,80
5 4 0,5432 31,12 0,0606 3,47 −1,9073 −109,28 −1,8066 −103,51 26,05
5 5 0,6148 35,23 0,0913 5,23 −1,8765 −107,52 −1,8374 −105,27 27,30
6 1 0,0000 0,00 0,0000 0,00 −1,6511 −94,60 −1,4204 −81,38 21,50
6 2 0,3331 19,08 0,0129 0,74 −1,6382 −93,86 −1,4333 −82,12 22,75
6 3 0,4605 26,39 0,0356 2,04 −1,6155 −92,56 −1,4560 −83,42 24,00
6 4 0,5520 31,63 0,0639 3,66 −1,5872 −90,94 −1,4843 −85,04 25,25
6 5 0,6244 35,78 0,0962 5,51 −1,5549 −89,09 −1,5166 −86,90 26,50
7 1 0,0000 0,00 0,0000 0,00 −1,3239 −75,86 −1,0858 −62,21 20,87
7 2 0,3378 19,35 0,0135 0,77 −1,3105 −75,08 −1,0993 −62,99 22,12
7 3 0,4668 26,74 0,0371 2,13 −1,2868 −73,73 −1,1230 −64,34 23,37
7 4 0,5592 32,04 0,0666 3,82 −1,2573 −72,04 −1,1525 −66,03 24,62
7 5 0,6322 36,22 0,1003 5,75 −1,2236 −70,11 −1,1861 −67,96 25,87
8 1 0,0000 0,00 0,0000 0,00 −0,9882 −56,62 −0,7444 −42,65 20,41
8 2 0,3414 19,56 0,0139 0,80 −0,9743 −55,82 −0,7583 −43,45 21,66
8 3 0,4715 27,02 0,0384 2,20 −0,9498 −54,42 −0,7827 −44,85 22,91
8 4 0,5646 32,35 0,0688 3,94 −0,9194 −52,68 −0,8132 −46,59 24,16
8 5 0,6381 36,56 0,1035 5,93 −0,8847 −50,69 −0,8479 −48,58 25,41
9 1 0,0000 0,00 0,0000 0,00 −0,6459 −37,01 −0,3982 −22,82 20,11
9 2 0,3438 19,70 0,0142 0,81 −0,6317 −36,19 −0,4124 −23,63 21,36
9 3 0,4747 27,20 0,0392 2,25 −0,6067 −34,76 −0,4374 −25,06 22,61
9 4 0,5683 32,56 0,0703 4,03 −0,5756 −32,98 −0,4685 −26,84 23,86
9 5 0,6420 36,79 0,1057 6,05 −0,5402 −30,95 −0,5039 −28,87 25,11
10 1 0,0000 0,00 0,0000 0,00 −0,2992 −17,14 −0,0496 −2,84 19,96
10 2 0,3450 19,77 0,0144 0,82 −0,2848 −16,32 −0,0640 −3,66 21,21
10 3 0,4763 27,29 0,0396 2,27 −0,2596 −14,87 −0,0892 −5,11 22,46
10 4 0,5701 32,66 0,0710 4,07 −0,2282 −13,07 −0,1206 −6,91 23,71
10 5 0,6440 36,90 0,1068 6,12 −0,1924 −11,02 −0,1564 −8,96 24,96
"""

TABLE4_SEED002 = """
1 1 0,0000 0,00 0,0000 0,00 −0,7610 −43,60 −0,7271 −41,66 92,23
1 2 0,1637 9,38 0,0015 0,08 −0,7625 −43,69 −0,7256 −41,57 93,48
1 3 0,2303 13,19 0,0042 0,24 −0,7652 −43,84 −0,7229 −41,42 94,73
1 4 0,2805 16,07 0,0076 0,44 −0,7686 −44,04 −0,7195 −41,22 95,98
1 5 0,3221 18,45 0,0116 0,67 −0,7726 −44,27 −0,7155 −40,99 97,23
1 6 0,3715 21,28 0,0181 1,04 – – −0,7090 −40,62 98,98
2 1 0,0000 0,00 0,0000 0,00 −0,6788 −38,89 −0,6454 −36,98 93,98
2 2 0,1622 9,29 0,0014 0,08 −0,6802 −38,97 −0,6440 −36,90 95,23
2 3 0,2281 13,07 0,0040 0,23 −0,6828 −39,12 −0,6414 −36,75 96,48
2 4 0,2779 15,92 0,0074 0,42 −0,6862 −39,31 −0,6380 −36,56 97,73
2 5 0,3192 18,29 0,0113 0,65 −0,6901 −39,54 −0,6341 −36,33 98,98
2 6 0,3611 20,69 0,0166 0,95 – – −0,6289 −36,03 100,46
3 1 0,0000 0,00 0,0000 0,00 −0,5980 −34,26 −0,5650 −32,37 95,46
3 2 0,1610 9,22 0,0014 0,08 −0,5994 −34,34 −0,5636 −32,29 96,71
3 3 0,2264 12,97 0,0039 0,23 −0,6019 −34,49 −0,5611 −32,15 97,96
3 4 0,2758 15,80 0,0072 0,41 −0,6052 −34,67 −0,5578 −31,96 99,21
3 5 0,3168 18,15 0,0110 0,63 −0,6090 −34,89 −0,5540 −31,74 100,46
3 6 0,3519 20,16 0,0153 0,88 – – −0,5498 −31,50 101,69
4 1 0,0000 0,00 0,0000 0,00 −0,5183 −29,70 −0,4857 −27,83 96,69
4 2 0,1599 9,16 0,0014 0,08 −0,5197 −29,78 −0,4843 −27,75 97,94
4 3 0,2250 12,89 0,0039 0,22 −0,5222 −29,92 −0,4819 −27,61 99,19
4 4 0,2741 15,71 0,0071 0,41 −0,5254 −30,10 −0,4786 −27,42 100,44
4 5 0,3149 18,04 0,0108 0,62 −0,5291 −30,32 −0,4749 −27,21 101,69
4 6 0,3438 19,70 0,0142 0,81 – – −0,4715 −27,02 102,70
5 1 0,0000 0,00 0,0000 0,00 −0,4396 −25,19 −0,4073 −23,34 97,70
5 2 0,1591 9,12 0,0014 0,08 −0,4409 −25,26 −0,4059 −23,26 98,95
5 3 0,2239 12,83 0,0038 0,22 −0,4434 −25,40 −0,4035 −23,12 100,20
5 4 0,2727 15,63 0,0070 0,40 −0,4465 −25,58 −0,4003 −22,94 101,45
5 5 0,3133 17,95 0,0107 0,61 −0,4502 −25,80 −0,3966 −22,72 102,70
5 6 0,3366 19,29 0,0133 0,76 – – −0,3940 −22,57 103,50
6 1 0,0000 0,00 0,0000 0,00 −0,3616 −20,72 −0,3295 −18,88 98,50
6 2 0,1585 9,08 0,0013 0,08 −0,3629 −20,79 −0,3282 −18,80 99,75
6 3 0,2230 12,77 0,0038 0,22 −0,3653 −20,93 −0,3257 −18,66 101,00
6 4 0,2717 15,56 0,0069 0,39 −0,3685 −21,11 −0,3226 −18,49 102,25
6 5 0,3121 17,88 0,0105 0,60 −0,3721 −21,32 −0,3190 −18,28 103,50
6 6 0,3302 18,92 0,0126 0,72 – – −0,3170 −18,16 104,13
7 1 0,0000 0,00 0,0000 0,00 −0,2842 −16,28 −0,2523 −14,45 99,13
7 2 0,1580 9,05 0,0013 0,08 −0,2855 −16,36 −0,2509 −14,38 100,38
7 3 0,2223 12,73 0,0037 0,21 −0,2879 −16,49 −0,2485 −14,24 101,63
7 4 0,2708 15,52 0,0068 0,39 −0,2910 −16,67 −0,2454 −14,06 102,88
7 5 0,3111 17,83 0,0104 0,60 −0,2946 −16,88 −0,2418 −13,86 104,13
7 6 0,3245 18,59 0,0119 0,68 – – −0,2404 −13,77 104,59
8 1 0,0000 0,00 0,0000 0,00 −0,2072 −11,87 −0,1754 −10,05 99,59
8 2 0,1576 9,03 0,0013 0,08 −0,2085 −11,95 −0,1741 −9,98 100,84
8 3 0,2218 12,71 0,0037 0,21 −0,2109 −12,08 −0,1717 −9,84 102,09
8 4 0,2702 15,48 0,0068 0,39 −0,2140 −12,26 −0,1686 −9,66 103,34
8 5 0,3105 17,79 0,0104 0,59 −0,2175 −12,46 −0,1650 −9,46 104,59
8 6 0,3193 18,29 0,0113 0,65 – – −0,1641 −9,40 104,89
9 1 0,0000 0,00 0,0000 0,00 −0,1305 −7,48 −0,0988 −5,66 99,89
9 2 0,1574 9,02 0,0013 0,08 −0,1318 −7,55 −0,0975 −5,59 101,14
9 3 0,2214 12,69 0,0037 0,21 −0,1342 −7,69 −0,0951 −5,45 102,39
9 4 0,2698 15,46 0,0067 0,39 −0,1372 −7,86 −0,0921 −5,28 103,64
9 5 0,3100 17,76 0,0103 0,59 −0,1408 −8,07 −0,0885 −5,07 104,89
9 6 0,3144 18,01 0,0108 0,62 – – −0,0880 −5,04 105,04
10 1 0,0000 0,00 0,0000 0,00 −0,0540 −3,10 −0,0224 −1,28 100,04
10 2 0,1573 9,01 0,0013 0,08 −0,0553 −3,17 −0,0211 −1,21 101,29
10 3 0,2213 12,68 0,0037 0,21 −0,0577 −3,31 −0,0187 −1,07 102,54
10 4 0,2696 15,45 0,0067 0,39 −0,0608 −3,48 −0,0157 −0,90 103,79
10 5 0,3098 17,75 0,0103 0,59 −0,0643 −3,69 −0,0121 −0,69 105,04
10 6 0,3098 17,75 0,0103 0,59 – – −0,0121 −0,69 105,04
"""


def parse_printed_table(text):
    """Rows of (value, decimals) pairs; a lone dash -> (None, None)."""
    rows = []
    for line in text.strip().splitlines():
        cells = []
        for tok in line.split():
            if tok in ("–", "—", "-"):
                cells.append((None, None))
                continue
            tok = tok.replace(",", ".").replace("−", "-").replace("–", "-")
            dec = len(tok.split(".")[1]) if "." in tok else 0
            cells.append((float(tok), dec))
        rows.append(cells)
    return rows


def assert_printed(computed, printed, where):
    """computed rounds to the printed value: |computed - printed| <= half a unit of the last digit."""
    value, dec = printed
    if value is None:
        assert computed is None or (isinstance(computed, float) and math.isnan(computed)), where
        return
    tol = 0.5 * 10.0 ** (-dec) * (1 + 1e-9) + 1e-12
    assert abs(computed - value) <= tol, f"{where}: computed {computed!r}, printed {value}"


# function scope: 0.08 s each, and mutation testing ties a test to the functions it calls itself (a module-scoped
# fixture's work counts for the first test using it only)
@pytest.fixture
def table000():
    return sector_table(WalkingLaw(**SEED_000), L=143.5, i=24)


@pytest.fixture
def table002():
    return sector_table(WalkingLaw(**SEED_002), L=125.0, i=20)


def _check_table1(table, text):
    printed = parse_printed_table(text)
    rows = table.rows()
    assert len(rows) == len(printed)
    for row, cells in zip(rows, printed):
        assert row["i"] == int(cells[0][0])
        for name, cell in zip(SECTOR_COLUMNS[1:], cells[1:]):
            assert_printed(row[name], cell, f"row {row['i']} {name}")


def test_table1_seed000_every_row(table000):
    _check_table1(table000, TABLE1_SEED000)


def test_table1_seed002_every_row(table002):
    _check_table1(table002, TABLE1_SEED002)


def test_table1_closure_and_equal_arcs(table000, table002):
    for t, n, arc in ((table000, 2, 6.2123), (table002, 4, 7.8346)):
        assert abs(t.dphi.sum() - math.pi / 2) < 1e-10
        assert abs(t.dtheta.sum() - n * math.pi / 2) < 1e-10
        arcs_H = t.r_H * t.dphi
        arcs = t.r * t.dtheta
        assert np.ptp(arcs_H) < 1e-9 and np.ptp(arcs) < 1e-9  # seed 000 eq. 52
        assert np.allclose(arcs_H, arcs, atol=1e-9)
        assert np.allclose(t.r + t.r_H, t.L)
        assert round(t.arc, 4) == arc  # SPEC §3 Trap 3: not pi*m
        # the table is symmetric about phi = 0 (the law is even)
        assert np.allclose(t.dphi, t.dphi[::-1], atol=1e-10)


def test_structured_equals_rows(table002):
    arr = table002.to_structured()
    assert arr.dtype.names == SECTOR_COLUMNS
    assert np.allclose(arr["r_mm"], [r["r_mm"] for r in table002.rows()])


def test_paper_tolerance_breaks_printed_symmetry():
    """Literal 1e-6 step criterion leaves a ~4e-5 rad closure residual (why we converge further)."""
    t = sector_table(WalkingLaw(**SEED_000), L=143.5, i=24, tol=1e-6)
    assert 1e-6 < abs(t.dphi.sum() - math.pi / 2) < 1e-4


def test_table2_seed002_every_row(table002):
    printed = parse_printed_table(TABLE2_SEED002)
    rows = sector_radii(table002, m=2.5).rows()
    assert len(rows) == len(printed) == 20
    cols = ("theta_deg", "r_mm", "r_b_mm", "r_f_mm", "r_a_mm", "phi_deg", "r_H_mm", "r_bH_mm", "r_fH_mm", "r_aH_mm")
    for row, cells in zip(rows, printed):
        assert row["i"] == int(cells[0][0])
        for name, cell in zip(cols, cells[1:]):
            assert_printed(row[name], cell, f"Table 2 row {row['i']} {name}")


def _check_points(arr, text, columns, n_points):
    printed = parse_printed_table(text)
    by_key = {(int(r["i"]), int(r["j"])): r for r in structured_rows(arr)}
    assert len(arr) == 20 * n_points
    for cells in printed:
        key = (int(cells[0][0]), int(cells[1][0]))
        row = by_key[key]
        for name, cell in zip(columns[2:], cells[2:]):
            assert_printed(row[name], cell, f"point {key} {name}")
    return len(printed)


def test_table3_seed002_every_row(table002):
    arr = pinion_tooth_points(table002, m=2.5, j_n=0.16)
    assert _check_points(arr, TABLE3_SEED002, PINION_POINT_COLUMNS, 5) == 50


def test_table4_seed002_every_row(table002):
    arr = wheel_space_points(table002, m=2.5, j_n=0.16)
    assert _check_points(arr, TABLE4_SEED002, WHEEL_POINT_COLUMNS, 6) == 60


def test_table3_needs_the_backlash(table002):
    """Without j_n = 0.16 mm the flank angles leave the printed digits (the rule is pinned)."""
    arr = pinion_tooth_points(table002, m=2.5, j_n=0.0)
    printed = parse_printed_table(TABLE3_SEED002)
    worst = 0.0
    for cells in printed:
        row = arr[(arr["i"] == cells[0][0]) & (arr["j"] == cells[1][0])][0]
        worst = max(worst, abs(row["theta_rad"] - cells[6][0]))
    assert worst > 1e-3


def test_tooth_is_half_sector_at_pitch_circle(table002):
    """Pinion tooth at the pitch circle spans dtheta/2 minus the backlash 2*delta."""
    arr = pinion_tooth_points(table002, m=2.5, j_n=0.16)
    p3 = arr[arr["j"] == 3]
    width = p3["theta_s_rad"] - p3["theta_rad"]
    r_b = table002.r - 2.5
    assert np.allclose(width, table002.dtheta / 2 - 2 * 0.16 / (4 * r_b), atol=1e-14)
    # polar angle of an involute point: inv alpha grows from 0 at the base circle
    assert np.all(arr["inv_rad"][arr["j"] == 1] == 0.0)
    assert np.allclose(involute(np.radians(20.0)), 0.014904383867336446)


def test_wheel_sixth_point_is_next_sector_tip(table002):
    arr = wheel_space_points(table002, m=2.5, j_n=0.16)
    p6 = arr[arr["j"] == 6]
    assert np.allclose(p6["r_H_mm"], np.roll(table002.r_H, -1) + 2.5)
    assert np.all(np.isnan(p6["phi_rad"]))


def test_sector_method_hub_speed_ripple(table000, table002):
    """SPEC §3 Trap 2: the staircase ratio leaves ~13 % (seed 000) and ~8 % (seed 002)."""
    r0 = sector_hub_speed(table000)
    r2 = sector_hub_speed(table002)
    assert 0.125 < r0.ripple < 0.135
    assert 0.078 < r2.ripple < 0.088
    law = table000.law
    assert r0.mean == pytest.approx(law.hub_speed_ratio, rel=1e-9)
    # the ripple sits at the hand-over sectors, the minimum at the leg edge
    assert abs(abs(r0.phi_min) - math.pi / 4) < 1e-9
    assert sector_ratio(table000, 0.01) == pytest.approx(table000.ratio[12])
    assert sector_ratio(table000, 0.01 + math.pi / 2) == pytest.approx(table000.ratio[12])


def test_other_parameters_close():
    law = WalkingLaw(a=80.0, b=70.0, c=300.0, n=1)
    t = sector_table(law, L=150.0, i=13)
    assert abs(t.dtheta.sum() - math.pi / 2) < 1e-10
    assert np.ptp(t.r_H * t.dphi) < 1e-9


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(L=-1.0, i=20), "L"),
        (dict(L=float("nan"), i=20), "L"),
        (dict(L=125.0, i=1), "i"),
        (dict(L=125.0, i=20.5), "i"),
    ],
)
def test_bad_input(kwargs, name):
    with pytest.raises(InputError) as e:
        sector_table(WalkingLaw(**SEED_002), **kwargs)
    assert e.value.parameter == name


def test_bad_module_backlash_and_n(table002):
    with pytest.raises(InputError) as e:
        sector_radii(table002, m=20.0)
    assert e.value.parameter == "m"
    with pytest.raises(InputError) as e:
        pinion_tooth_points(table002, m=2.5, j_n=-0.1)
    assert e.value.parameter == "j_n"
    with pytest.raises(InputError) as e:
        sector_table(WalkingLaw(a=60, b=100, c=360, n=3), L=140.0, i=24)
    assert e.value.parameter == "n" and "n divides" in str(e.value)


def test_sector_ratio_at_every_sector(table000, table002):
    """The staircase ratio on each sector's own interval: its midpoint, just inside both ends, and one
    leg later, for every sector of both seeds (neighbouring sectors differ, so an index off by one
    cannot pass)."""
    for t in (table000, table002):
        # neighbours differ, but for the middle pair of an even count (the law is even about w = 0)
        assert np.count_nonzero(np.abs(np.diff(t.ratio)) < 1e-6) == (1 - t.i % 2)
        for k in range(t.i):
            lo, hi = t.phi[k], t.phi[k] + t.dphi[k]
            for phi in (0.5 * (lo + hi), lo + 1e-9, hi - 1e-9):
                assert sector_ratio(t, phi) == t.ratio[k], (t.i, k, phi)
                assert sector_ratio(t, phi + math.pi / 2) == t.ratio[k]
        phis = np.array([t.phi[k] + 0.5 * t.dphi[k] for k in range(t.i)])
        assert np.array_equal(sector_ratio(t, phis), t.ratio)


@pytest.mark.parametrize("j_n", [0.0, 0.16, 0.5])
def test_tip_land_thickness_from_the_tables_points(table002, j_n):
    """The least tip land of the sector method's teeth, read off Tables 3 and 4 themselves: a driver tooth's land is
    (r + m)(theta_s - theta) at its tip point j = 5; a driven tooth lies between space i (its second flank's 6th point,
    on the next sector's tip circle r_H(i+1) + m) and space i + 1 (its first flank's 5th point on the same circle;
    the last space's neighbour is the next leg's first, pi/2 on)."""
    m = 2.5
    drv = pinion_tooth_points(table002, m=m, j_n=j_n)
    tip = drv[drv["j"] == 5]
    t_drv = float(np.min(tip["r_mm"] * (tip["theta_s_rad"] - tip["theta_rad"])))
    whl = wheel_space_points(table002, m=m, j_n=j_n)
    sixth = whl[whl["j"] == 6]
    fifth = whl[whl["j"] == 5]
    nxt = np.roll(fifth["phi_rad"], -1)
    nxt[-1] += math.pi / 2
    assert np.allclose(np.roll(fifth["r_H_mm"], -1), sixth["r_H_mm"], rtol=0, atol=1e-12)
    t_dvn = float(np.min(sixth["r_H_mm"] * (nxt - sixth["phi_s_rad"])))
    got = sector_tip_thickness(table002, m, j_n)
    assert got == pytest.approx((t_drv, t_dvn), rel=1e-12)
    assert 0 < got[0] and 0 < got[1]


def test_radii_structured_equals_rows(table002):
    radii = sector_radii(table002, m=2.5)
    arr = radii.to_structured()
    assert arr.dtype.names == RADII_COLUMNS
    assert structured_rows(arr) == radii.rows()


def test_backlash_and_module_refusals_in_full(table002):
    for fn in (pinion_tooth_points, wheel_space_points):
        with pytest.raises(InputError) as e:
            fn(table002, 2.5, -0.1)
        assert str(e.value) == "j_n = -0.1: backlash must be >= 0 mm" and e.value.parameter == "j_n"
        with pytest.raises(InputError) as e:
            fn(table002, 2.5, float("nan"))
        assert str(e.value) == "j_n = nan: must be a finite number"
        assert len(fn(table002, 2.5, 0.0)) > 0
    with pytest.raises(InputError) as e:
        sector_radii(table002, 0.0)
    assert str(e.value) == "m = 0.0: must be > 0 mm"
    # the driver's root radius r - 1.25 m must stay positive on every sector: m < min(r) / 1.25
    m_lim = float(np.min(table002.r)) / 1.25
    assert sector_radii(table002, m_lim * 0.999).m == m_lim * 0.999
    with pytest.raises(InputError) as e:
        sector_radii(table002, m_lim)
    assert str(e.value) == f"m = {m_lim}: root radius r - 1.25 m must be > 0: m < {m_lim:.4f} mm"


def test_rows_keep_integer_indices_and_the_papers_dashes(table002):
    arr = wheel_space_points(table002, 2.5, 0.16)
    assert arr.dtype["i"] == np.int64 and arr.dtype["j"] == np.int64 and arr.dtype["phi_rad"] == np.float64
    rows = structured_rows(arr)
    assert all(type(r["i"]) is int and type(r["j"]) is int for r in rows)
    sixth = [r for r in rows if r["j"] == 6]
    assert len(sixth) == 20 and all(r["phi_rad"] is None and r["phi_deg"] is None for r in sixth)
    assert all(isinstance(r["phi_s_rad"], float) for r in sixth)
    radii = sector_radii(table002, 2.5).rows()
    assert type(radii[0]["i"]) is int and [r["i"] for r in radii] == list(range(1, 21))


def test_sector_ratio_at_the_edges_of_the_sectors(table002):
    """Each sector's ratio holds from its first angle (inclusive) to the next sector's; the last sector runs to the
    leg's end, pi/4, which its computed end (phi + dphi) misses by rounding."""
    t = table002
    for k in range(1, t.i):
        assert float(sector_ratio(t, t.phi[k])) == t.ratio[k]
        assert float(sector_ratio(t, t.phi[k] - 1e-9)) == t.ratio[k - 1]
    assert float(t.phi[-1] + t.dphi[-1]) < math.pi / 4
    assert float(sector_ratio(t, math.pi / 4 - 1e-13)) == t.ratio[-1]
    assert float(sector_ratio(t, -math.pi / 4)) == t.ratio[0]


def test_sector_hub_speed_by_hand(table002):
    """v / omega = (dX01/dphi) / U_k on each sector's samples; the extremes and where they are, at the default and at
    2 samples a sector (its ends only: v is monotone within each sector of seed 002, so both find the same extremes)."""
    t = table002
    law = t.law

    def by_hand(n):
        phis = np.concatenate([np.linspace(t.phi[k], t.phi[k] + t.dphi[k], n) for k in range(t.i)])
        v = np.concatenate([law.dX01_dphi(np.linspace(t.phi[k], t.phi[k] + t.dphi[k], n)) / t.ratio[k]
                            for k in range(t.i)])
        return phis, v

    for n in (400, 2):
        phis, v = by_hand(n)
        got = sector_hub_speed(t, n) if n != 400 else sector_hub_speed(t)
        assert got.v_min == pytest.approx(float(v.min()), rel=1e-14)
        assert got.v_max == pytest.approx(float(v.max()), rel=1e-14)
        assert got.phi_min == float(phis[np.argmin(v)]) and got.phi_max == float(phis[np.argmax(v)])
        assert got.ripple == pytest.approx((v.max() - v.min()) / got.mean, rel=1e-13)


def test_sector_table_refusals_in_full():
    """Each refusal names the parameter, its value and the limit; the limits' accepted sides too (2 sectors a leg)."""
    law = WalkingLaw(**SEED_002)
    cases = [
        (dict(law="seed 002", L=125.0, i=20), "law = 'seed 002': must be a WalkingLaw"),
        (dict(law=law, L=-1.0, i=20), "L = -1.0: must be > 0 mm"),
        (dict(law=law, L=125.0, i=float("nan")), "i = nan: must be a finite number"),
        (dict(law=law, L=125.0, i=1), "i = 1: sectors per leg must be a whole number >= 2"),
        (dict(law=law, L=125.0, i=20.5), "i = 20.5: sectors per leg must be a whole number >= 2"),
        (dict(law=law, L=125.0, i=20, tol=0.0), "tol = 0.0: must be > 0 rad"),
        (dict(law=law, L=125.0, i=20, tol=float("nan")), "tol = nan: must be a finite number"),
        # seed 000 eqs. 25-31 need 35 cycles for seed 002 at i = 20 (tol 1e-13 rad)
        (dict(law=law, L=125.0, i=20, max_iter=34),
         "i = 20: sector iteration (seed 000 eqs. 25-31) did not converge in 34 cycles"),
        # a steep law on 6 sectors: eq. 39-40's denominator dtheta_(k-1) (dphi_k - dphi_(k-1)) + dphi_(k-1) dphi_k
        # turns negative where the driven intervals shrink fast
        (dict(law=WalkingLaw(a=20, b=100, c=100, n=4), L=140.0, i=6),
         "L = 140.0: driver sector recursion (seed 000 eq. 39-40) gave a non-positive interval"),
    ]
    for kwargs, text in cases:
        with pytest.raises(InputError) as e:
            sector_table(**kwargs)
        assert str(e.value) == text
        assert e.value.parameter == text.split(" = ")[0]
    t = sector_table(law, L=125.0, i=2)  # two sectors: the law is even, each takes half the leg
    assert t.i == 2 and np.allclose(t.dphi, math.pi / 4, atol=1e-12) and np.allclose(t.dtheta, math.pi, atol=1e-12)
    assert sector_table(law, L=125.0, i=20, max_iter=35).i == 20


def test_driver_iteration_refusal_in_full():
    """seed 000 eqs. 48-51 stopped before they converge name the sector count and the cycles allowed."""
    from propulsor.gears.sectors import _driver_intervals

    dphi = np.array([0.3, 0.4, 0.5, 0.3707963267948966])
    with pytest.raises(InputError) as e:
        _driver_intervals(dphi, math.pi, 1e-13, 1, 125.0)
    assert str(e.value) == "i = 4: driver sector iteration (seed 000 eqs. 48-51) did not converge in 1 cycles"
    assert e.value.parameter == "i"
    dth = _driver_intervals(dphi, math.pi, 1e-13, 10000, 125.0)
    # eq. 39-40 keep the arc r_Hk dphi_k = L / (1/dphi_k + 1/dtheta_k) (r_H = L dtheta / (dphi + dtheta)) the same
    q = 1 / dth + 1 / dphi
    assert np.ptp(q) < 1e-12 and abs(dth.sum() - math.pi) < 1e-12


def test_a_phi_that_wraps_a_hair_below_the_legs_start_is_the_first_sector(table002):
    """wrap_leg of -pi/4 + 1999 pi/2 lands one rounding below -pi/4 (before the first edge): still sector 1, not
    the last (the two ratios differ by 1e-11 in seed 002's table)."""
    from propulsor.laws.walking import wrap_leg

    phi = -math.pi / 4 + 1999 * math.pi / 2
    assert float(wrap_leg(phi)) < -math.pi / 4
    assert table002.ratio[0] != table002.ratio[-1]
    assert float(sector_ratio(table002, phi)) == table002.ratio[0]


def test_sixth_point_inside_the_base_circle_takes_the_involutes_start():
    """seed 002 eq. 15-16 put the 6th point of space k on the next sector's tip circle r_H(k+1) + m; a steep law on 3
    sectors drops r_H by 8.14 mm from sector 2 to 3, so with m = 3 that circle (93.45 mm) lies inside sector 2's base
    circle r_H - m = 95.59 mm: the point is the involute's start (alpha = 0, inv = 0), not a NaN, and the tip land
    stays a number."""
    t = sector_table(WalkingLaw(a=60, b=100, c=360, n=2), L=140.0, i=3)
    m, j_n = 3.0, 0.1
    assert t.r_H[2] + m < t.r_H[1] - m
    whl = wheel_space_points(t, m, j_n)
    six = whl[(whl["i"] == 2) & (whl["j"] == 6)][0]
    assert six["alpha_rad"] == 0.0 and six["inv_rad"] == 0.0
    nu3 = math.tan(math.acos((t.r_H[1] - m) / t.r_H[1])) - math.acos((t.r_H[1] - m) / t.r_H[1])
    d_H = j_n / (4 * (t.r_H[1] - m))
    assert six["phi_s_rad"] == pytest.approx(t.phi[1] + 0.75 * t.dphi[1] + d_H - nu3, abs=1e-14)
    cols = [c for c in WHEEL_POINT_COLUMNS if c not in ("phi_rad", "phi_deg")]
    assert all(np.all(np.isfinite(whl[c])) for c in cols)
    t_drv, t_dvn = sector_tip_thickness(t, m, j_n)
    assert math.isfinite(t_drv) and math.isfinite(t_dvn)
    sixth, fifth = whl[whl["j"] == 6], whl[whl["j"] == 5]
    nxt = np.roll(fifth["phi_rad"], -1)
    nxt[-1] += math.pi / 2
    assert t_dvn == pytest.approx(float(np.min(sixth["r_H_mm"] * (nxt - sixth["phi_s_rad"]))), rel=1e-12)


def test_tip_land_of_the_last_driven_tooth_reaches_into_the_next_leg():
    """On a circular table (equal radii and pitches: a spur gear cut by the sector rules) every tooth's tip land is the
    textbook s_a = r_a (pitch angle / 2 - 2 delta - 2 (inv alpha_a - inv alpha)) with cos alpha = r_b / r; widen the
    last space by 0.01 rad and only the tooth between it and the next leg's first space thins, by 0.75 * 0.01 r_a."""
    from dataclasses import replace

    i, m, j_n = 8, 2.0, 0.2
    d = math.pi / 2 / i
    phi = -math.pi / 4 + d * np.arange(i)
    base = sector_table(WalkingLaw(**SEED_002), L=125.0, i=20)
    r_H, r = 60.0, 40.0
    dth = 2 * math.pi / i
    t = replace(base, L=100.0, phi=phi, dphi=np.full(i, d), r_H=np.full(i, r_H),
                theta=-math.pi + dth * np.arange(i), dtheta=np.full(i, dth), r=np.full(i, r))

    def land(rad, pitch_angle):
        r_b, r_a = rad - m, rad + m
        a, a_a = math.acos(r_b / rad), math.acos(r_b / r_a)
        inv, inv_a = math.tan(a) - a, math.tan(a_a) - a_a
        return r_a * (pitch_angle / 2 - 2 * j_n / (4 * r_b) - 2 * (inv_a - inv))

    t_drv, t_dvn = sector_tip_thickness(t, m, j_n)
    assert t_drv == pytest.approx(land(r, dth), rel=1e-12)
    assert t_dvn == pytest.approx(land(r_H, d), rel=1e-12)
    dphi = np.full(i, d)
    dphi[-1] += 0.01
    _, t_last = sector_tip_thickness(replace(t, dphi=dphi), m, j_n)
    assert t_last == pytest.approx(land(r_H, d) - 0.75 * 0.01 * (r_H + m), rel=1e-12)


def test_hub_speed_of_a_table_stopped_early_finds_its_least_speed_at_the_legs_end():
    """Stopped at 1e-3 rad the method leaves its last sector short (the leg ends at 0.7646 rad, not pi/4): the least
    hub speed is at that end, not at the leg's start; the extremes by hand as in test_sector_hub_speed_by_hand."""
    t = sector_table(WalkingLaw(**SEED_002), L=125.0, i=20, tol=1e-3)
    law = t.law
    phis = np.concatenate([np.linspace(t.phi[k], t.phi[k] + t.dphi[k], 400) for k in range(t.i)])
    v = np.concatenate([law.dX01_dphi(np.linspace(t.phi[k], t.phi[k] + t.dphi[k], 400)) / t.ratio[k]
                        for k in range(t.i)])
    got = sector_hub_speed(t)
    assert got.phi_min == float(phis[np.argmin(v)]) == pytest.approx(t.phi[-1] + t.dphi[-1], abs=1e-15)
    assert got.phi_min > 0.76
    assert got.v_min == pytest.approx(float(v.min()), rel=1e-14)
    assert got.phi_max == float(phis[np.argmax(v)]) and got.v_max == pytest.approx(float(v.max()), rel=1e-14)
