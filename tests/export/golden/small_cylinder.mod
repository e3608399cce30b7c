MODULE small_cylinder
  ! Spira @VERSION@ WAAM deposition program
  ! part: cylinder_r20.stl
  ! cell: test cell
  ! date: 2024-05-01 12:30:00
  ! decomposer: decomposer.isovalue
  ! h: 2 mm
  ! module: small_cylinder
  ! points: 25, path 367.425 mm
  ! frames: tSpiraTorch (the cell's torch TCP), wobjSpira (identity)
  ! targets: torch TCP in the robot base frame of the solved cell, with confdata
  ! positioner: E1/E2 in eax_a/eax_b, moving with each move (not coordinated)
  ! zone: z1 inside arcs
  ! process: speed_analog, schedule 1, wire feed in welddata
  PERS tooldata tSpiraTorch := [TRUE,[[0.000,0.000,350.000],[1.00000000,0.00000000,0.00000000,0.00000000]],[3.000,[0.0,0.0,175.0],[1,0,0,0],0,0,0]];
  PERS wobjdata wobjSpira := [FALSE,TRUE,"",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS seamdata smSpira := [0.5,0.5,[1,0,0.0,0,0,0,0,0,0],0,0,0,0,0,[1,0,0.0,0,0,0,0,0,0],0,0,[1,0,0.0,0,0,0,0,0,0],0,0,[1,0,0.0,0,0,0,0,0,0],0.5];
  PERS welddata wdSpira1 := [8.00,0,[1,0,0.0,3.35,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira2 := [8.00,0,[1,0,0.0,3.50,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira3 := [8.00,0,[1,0,0.0,3.00,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira4 := [8.00,0,[1,0,0.0,2.65,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira5 := [8.00,0,[1,0,0.0,2.50,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira6 := [10.0,0,[1,0,0.0,3.00,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira7 := [10.0,0,[1,0,0.0,3.35,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira8 := [10.0,0,[1,0,0.0,3.50,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira9 := [10.0,0,[1,0,0.0,2.65,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS welddata wdSpira10 := [10.0,0,[1,0,0.0,2.50,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  CONST speeddata vSpira1 := [8.00,500,5000,1000];
  CONST speeddata vSpira2 := [10.0,500,5000,1000];
  CONST speeddata vSpiraApproach := [20.0,500,5000,1000];
  CONST speeddata vSpiraTravel := [200.0,500,5000,1000];
  CONST robtarget pApproach := [[1017.480,-190.276,419.997],[0.00689096,-0.49998417,-0.86599799,-0.00397850],[-1,0,1,1],[-30.0000,0.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p0 := [[1017.321,-190.000,400.000],[0.00689096,-0.49998417,-0.86599799,-0.00397850],[-1,0,1,1],[-30.0000,0.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[1005.176,-180.681,400.250],[0.00791616,-0.15975908,-0.98712397,-0.00080504],[-1,0,1,1],[-29.7500,5.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[990.000,-182.679,400.500],[0.00755739,0.20388882,-0.97896171,0.00248988],[-1,0,1,1],[-29.5000,10.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[980.681,-194.824,400.750],[0.00591430,0.54479549,-0.83853119,0.00532304],[-1,0,1,1],[-29.2500,15.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p4 := [[982.679,-210.000,401.000],[0.00331989,0.81570622,-0.57841166,0.00723132],[-1,0,1,1],[-29.0000,20.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p5 := [[994.824,-219.319,401.250],[0.00024782,0.97348737,-0.22860234,0.00795313],[-1,0,1,1],[-28.7500,25.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p6 := [[1010.000,-217.321,401.500],[0.00279697,-0.98648311,-0.16366970,-0.00744921],[-1,0,1,1],[-28.5000,30.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p7 := [[1019.319,-205.176,401.750],[0.00537012,-0.84285635,-0.53807978,-0.00587159],[-1,0,1,1],[-28.2500,35.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p8 := [[1017.321,-190.000,402.000],[0.00714377,-0.55729452,-0.83027676,-0.00350432],[-1,0,1,1],[-28.0000,40.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p9 := [[1005.176,-180.681,402.250],[0.00792609,-0.17276100,-0.98493163,-0.00070059],[-1,0,1,1],[-27.7500,45.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p10 := [[990.000,-182.679,402.500],[0.00765604,0.24515482,-0.96945129,0.00216768],[-1,0,1,1],[-27.5000,50.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p11 := [[980.681,-194.824,402.750],[0.00638833,0.62118031,-0.78362727,0.00474373],[-1,0,1,1],[-27.2500,55.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p12 := [[982.679,-210.000,403.000],[0.00427944,0.88726831,-0.46118503,0.00670821],[-1,0,1,1],[-27.0000,60.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p13 := [[994.824,-219.319,403.250],[0.00157829,0.99803939,-0.06208116,0.00779889],[-1,0,1,1],[-26.7500,65.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p14 := [[1010.000,-217.321,403.500],[0.00138257,-0.93970011,-0.34190700,-0.00783596],[-1,0,1,1],[-26.5000,70.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p15 := [[1019.319,-205.176,403.750],[0.00420468,-0.73012920,-0.68326278,-0.00675532],[-1,0,1,1],[-26.2500,75.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p16 := [[1017.321,-190.000,404.000],[0.00646113,-0.41138039,-0.91142902,-0.00464409],[-1,0,1,1],[-26.0000,80.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p17 := [[1005.176,-180.681,404.250],[0.00775912,-0.03830764,-0.99923431,-0.00176347],[-1,0,1,1],[-25.7500,85.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p18 := [[990.000,-182.679,404.500],[0.00782191,0.33260516,-0.94303260,0.00145993],[-1,0,1,1],[-25.5000,90.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p19 := [[980.681,-194.824,404.750],[0.00656975,0.65148473,-0.75862002,0.00448911],[-1,0,1,1],[-25.2500,95.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[982.679,-210.000,405.000],[0.00416946,0.87962847,-0.47559483,0.00677712],[-1,0,1,1],[-25.0000,100.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p21 := [[994.824,-219.319,405.250],[0.00102533,0.99119262,-0.13218883,0.00789065],[-1,0,1,1],[-24.7500,105.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p22 := [[1010.000,-217.321,405.500],[0.00229783,-0.97348827,-0.22859850,-0.00761798],[-1,0,1,1],[-24.5000,110.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p23 := [[1019.319,-205.176,405.750],[0.00520076,-0.82719382,-0.56186037,-0.00602211],[-1,0,1,1],[-24.2500,115.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget p24 := [[1017.321,-190.000,406.000],[0.00718469,-0.56706962,-0.82363143,-0.00341963],[-1,0,1,1],[-24.0000,120.0000,9E9,9E9,9E9,9E9]];
  CONST robtarget pRetract := [[1017.480,-190.276,425.997],[0.00718469,-0.56706962,-0.82363143,-0.00341963],[-1,0,1,1],[-24.0000,120.0000,9E9,9E9,9E9,9E9]];
  PROC main()
    ConfJ \On;
    ConfL \Off;
    MoveJ pApproach, vSpiraTravel, fine, tSpiraTorch \WObj:=wobjSpira;
    ArcLStart p0, vSpiraApproach, smSpira, wdSpira1, fine, tSpiraTorch \WObj:=wobjSpira;
    ArcL p1, vSpira1, smSpira, wdSpira1, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p2, vSpira1, smSpira, wdSpira2, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p3, vSpira1, smSpira, wdSpira1, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p4, vSpira1, smSpira, wdSpira3, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p5, vSpira1, smSpira, wdSpira4, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p6, vSpira1, smSpira, wdSpira5, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p7, vSpira1, smSpira, wdSpira4, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p8, vSpira2, smSpira, wdSpira6, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p9, vSpira2, smSpira, wdSpira7, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p10, vSpira2, smSpira, wdSpira8, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p11, vSpira2, smSpira, wdSpira7, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p12, vSpira2, smSpira, wdSpira6, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p13, vSpira2, smSpira, wdSpira9, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p14, vSpira2, smSpira, wdSpira10, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p15, vSpira2, smSpira, wdSpira9, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p16, vSpira2, smSpira, wdSpira6, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p17, vSpira2, smSpira, wdSpira7, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p18, vSpira2, smSpira, wdSpira8, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p19, vSpira2, smSpira, wdSpira7, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p20, vSpira2, smSpira, wdSpira6, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p21, vSpira2, smSpira, wdSpira9, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p22, vSpira2, smSpira, wdSpira10, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcL p23, vSpira2, smSpira, wdSpira9, z1, tSpiraTorch \WObj:=wobjSpira;
    ArcLEnd p24, vSpira2, smSpira, wdSpira6, fine, tSpiraTorch \WObj:=wobjSpira;
    MoveL pRetract, vSpiraApproach, fine, tSpiraTorch \WObj:=wobjSpira;
  ENDPROC
ENDMODULE
