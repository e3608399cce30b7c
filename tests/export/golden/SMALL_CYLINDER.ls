/PROG  SMALL_CYLINDER
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "Spira WAAM";
PROG_SIZE	= 0;
CREATE		= DATE 24-05-01  TIME 12:30:00;
MODIFIED	= DATE 24-05-01  TIME 12:30:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 47;
MEMORY_SIZE	= 0;
PROTECT		= READ_WRITE;
TCD:  STACK_SIZE	= 0,
      TASK_PRIORITY	= 50,
      TIME_SLICE	= 0,
      BUSY_LAMP_OFF	= 0,
      ABORT_REQUEST	= 0,
      PAUSE_REQUEST	= 0;
DEFAULT_GROUP	= 1,1,*,*,*;
CONTROL_CODE	= 00000000 00000000;
/APPL
  ARC : TRUE ;
  ARC Welding Equipment : 1,*,*,*,*;
/MN
   1:  !Spira @VERSION@ WAAM deposition ;
   2:  !program ;
   3:  !part: cylinder_r20.stl ;
   4:  !cell: test cell ;
   5:  !date: 2024-05-01 12:30:00 ;
   6:  !decomposer: decomposer.isovalue ;
   7:  !h: 2 mm ;
   8:  !program: SMALL_CYLINDER ;
   9:  !points: 25, path 367.4 mm ;
  10:  !frames: UFRAME 0, UTOOL 1 ;
  11:  !targets: TCP in World of the ;
  12:  !solved cell ;
  13:  !positioner: GP2, not coordinated ;
  14:  !speed: msec, CNT100 ;
  15:  !process: speed_analog, Arc ;
  16:  !Start[3], Arc End[4], WFS AO[1] ;
  17:  UTOOL_NUM=1 ;
  18:  UFRAME_NUM=0 ;
  19:J P[1] 20% FINE ;
  20:L P[2] 1000msec FINE TA 0.00sec,AO[1]=3354 ;
  21:  Arc Start[3] ;
  22:L P[3] 1914msec CNT100 TA 0.00sec,AO[1]=3500 ;
  23:L P[4] 1914msec CNT100 TA 0.00sec,AO[1]=3354 ;
  24:L P[5] 1914msec CNT100 TA 0.00sec,AO[1]=3000 ;
  25:L P[6] 1914msec CNT100 TA 0.00sec,AO[1]=2646 ;
  26:L P[7] 1914msec CNT100 TA 0.00sec,AO[1]=2500 ;
  27:L P[8] 1914msec CNT100 TA 0.00sec,AO[1]=2646 ;
  28:L P[9] 1914msec CNT100 TA 0.00sec,AO[1]=3000 ;
  29:L P[10] 1531msec CNT100 TA 0.00sec,AO[1]=3354 ;
  30:L P[11] 1531msec CNT100 TA 0.00sec,AO[1]=3500 ;
  31:L P[12] 1531msec CNT100 TA 0.00sec,AO[1]=3354 ;
  32:L P[13] 1531msec CNT100 TA 0.00sec,AO[1]=3000 ;
  33:L P[14] 1531msec CNT100 TA 0.00sec,AO[1]=2646 ;
  34:L P[15] 1531msec CNT100 TA 0.00sec,AO[1]=2500 ;
  35:L P[16] 1531msec CNT100 TA 0.00sec,AO[1]=2646 ;
  36:L P[17] 1531msec CNT100 TA 0.00sec,AO[1]=3000 ;
  37:L P[18] 1531msec CNT100 TA 0.00sec,AO[1]=3354 ;
  38:L P[19] 1531msec CNT100 TA 0.00sec,AO[1]=3500 ;
  39:L P[20] 1531msec CNT100 TA 0.00sec,AO[1]=3354 ;
  40:L P[21] 1531msec CNT100 TA 0.00sec,AO[1]=3000 ;
  41:L P[22] 1531msec CNT100 TA 0.00sec,AO[1]=2646 ;
  42:L P[23] 1531msec CNT100 TA 0.00sec,AO[1]=2500 ;
  43:L P[24] 1531msec CNT100 TA 0.00sec,AO[1]=2646 ;
  44:L P[25] 1531msec CNT100 TA 0.00sec,AO[1]=3000 ;
  45:L P[26] 1531msec FINE ;
  46:  Arc End[4] ;
  47:L P[27] 1000msec FINE ;
/POS
P[1]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.480  mm,	Y =  -190.276  mm,	Z =   419.997  mm,
	W =   180.0000 deg,	P =    -0.9118 deg,	R =   120.0000 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -30.0000 deg,	J2=     0.0000 deg
};
P[2]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.321  mm,	Y =  -190.000  mm,	Z =   400.000  mm,
	W =   180.0000 deg,	P =    -0.9118 deg,	R =   120.0000 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -30.0000 deg,	J2=     0.0000 deg
};
P[3]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1005.176  mm,	Y =  -180.681  mm,	Z =   400.250  mm,
	W =  -179.9461 deg,	P =    -0.9102 deg,	R =   161.6132 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -29.7500 deg,	J2=     5.0000 deg
};
P[4]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   990.000  mm,	Y =  -182.679  mm,	Z =   400.500  mm,
	W =  -179.8972 deg,	P =    -0.9060 deg,	R =  -156.4711 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -29.5000 deg,	J2=    10.0000 deg
};
P[5]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   980.681  mm,	Y =  -194.824  mm,	Z =   400.750  mm,
	W =  -179.8577 deg,	P =    -0.9006 deg,	R =  -113.9774 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -29.2500 deg,	J2=    15.0000 deg
};
P[6]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   982.679  mm,	Y =  -210.000  mm,	Z =   401.000  mm,
	W =  -179.8310 deg,	P =    -0.8960 deg,	R =   -70.6817 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -29.0000 deg,	J2=    20.0000 deg
};
P[7]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   994.824  mm,	Y =  -219.319  mm,	Z =   401.250  mm,
	W =  -179.8193 deg,	P =    -0.8937 deg,	R =   -26.4319 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -28.7500 deg,	J2=    25.0000 deg
};
P[8]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1010.000  mm,	Y =  -217.321  mm,	Z =   401.500  mm,
	W =  -179.8235 deg,	P =    -0.8946 deg,	R =    18.8392 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -28.5000 deg,	J2=    30.0000 deg
};
P[9]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1019.319  mm,	Y =  -205.176  mm,	Z =   401.750  mm,
	W =  -179.8434 deg,	P =    -0.8983 deg,	R =    65.1071 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -28.2500 deg,	J2=    35.0000 deg
};
P[10]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.321  mm,	Y =  -190.000  mm,	Z =   402.000  mm,
	W =  -179.8772 deg,	P =    -0.9035 deg,	R =   112.2588 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -28.0000 deg,	J2=    40.0000 deg
};
P[11]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1005.176  mm,	Y =  -180.681  mm,	Z =   402.250  mm,
	W =  -179.9222 deg,	P =    -0.9085 deg,	R =   160.1020 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -27.7500 deg,	J2=    45.0000 deg
};
P[12]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   990.000  mm,	Y =  -182.679  mm,	Z =   402.500  mm,
	W =  -179.9743 deg,	P =    -0.9115 deg,	R =  -151.6173 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -27.5000 deg,	J2=    50.0000 deg
};
P[13]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   980.681  mm,	Y =  -194.824  mm,	Z =   402.750  mm,
	W =   179.9712 deg,	P =    -0.9114 deg,	R =  -103.1921 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -27.2500 deg,	J2=    55.0000 deg
};
P[14]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   982.679  mm,	Y =  -210.000  mm,	Z =   403.000  mm,
	W =   179.9194 deg,	P =    -0.9082 deg,	R =   -54.9285 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -27.0000 deg,	J2=    60.0000 deg
};
P[15]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   994.824  mm,	Y =  -219.319  mm,	Z =   403.250  mm,
	W =   179.8750 deg,	P =    -0.9032 deg,	R =    -7.1178 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -26.7500 deg,	J2=    65.0000 deg
};
P[16]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1010.000  mm,	Y =  -217.321  mm,	Z =   403.500  mm,
	W =   179.8418 deg,	P =    -0.8980 deg,	R =    39.9888 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -26.5000 deg,	J2=    70.0000 deg
};
P[17]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1019.319  mm,	Y =  -205.176  mm,	Z =   403.750  mm,
	W =   179.8229 deg,	P =    -0.8944 deg,	R =    86.2031 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -26.2500 deg,	J2=    75.0000 deg
};
P[18]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.321  mm,	Y =  -190.000  mm,	Z =   404.000  mm,
	W =   179.8195 deg,	P =    -0.8938 deg,	R =   131.4166 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -26.0000 deg,	J2=    80.0000 deg
};
P[19]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1005.176  mm,	Y =  -180.681  mm,	Z =   404.250  mm,
	W =   179.8321 deg,	P =    -0.8962 deg,	R =   175.6104 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -25.7500 deg,	J2=    85.0000 deg
};
P[20]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   990.000  mm,	Y =  -182.679  mm,	Z =   404.500  mm,
	W =   179.8596 deg,	P =    -0.9009 deg,	R =  -141.1437 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -25.5000 deg,	J2=    90.0000 deg
};
P[21]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   980.681  mm,	Y =  -194.824  mm,	Z =   404.750  mm,
	W =   179.8998 deg,	P =    -0.9063 deg,	R =   -98.6888 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -25.2500 deg,	J2=    95.0000 deg
};
P[22]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   982.679  mm,	Y =  -210.000  mm,	Z =   405.000  mm,
	W =   179.9491 deg,	P =    -0.9104 deg,	R =   -56.7977 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -25.0000 deg,	J2=   100.0000 deg
};
P[23]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =   994.824  mm,	Y =  -219.319  mm,	Z =   405.250  mm,
	W =  -179.9969 deg,	P =    -0.9118 deg,	R =   -15.1927 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -24.7500 deg,	J2=   105.0000 deg
};
P[24]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1010.000  mm,	Y =  -217.321  mm,	Z =   405.500  mm,
	W =  -179.9432 deg,	P =    -0.9100 deg,	R =    26.4295 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -24.5000 deg,	J2=   110.0000 deg
};
P[25]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1019.319  mm,	Y =  -205.176  mm,	Z =   405.750  mm,
	W =  -179.8947 deg,	P =    -0.9057 deg,	R =    68.3707 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -24.2500 deg,	J2=   115.0000 deg
};
P[26]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.321  mm,	Y =  -190.000  mm,	Z =   406.000  mm,
	W =  -179.8559 deg,	P =    -0.9003 deg,	R =   110.9041 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -24.0000 deg,	J2=   120.0000 deg
};
P[27]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  1017.480  mm,	Y =  -190.276  mm,	Z =   425.997  mm,
	W =  -179.8559 deg,	P =    -0.9003 deg,	R =   110.9041 deg
   GP2:
	UF : 0, UT : 1,
	J1=   -24.0000 deg,	J2=   120.0000 deg
};
/END
