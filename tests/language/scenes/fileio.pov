// Language test: #fopen (write, append, read), #write of strings, floats
// and vectors, #read of string, float and vector data back into new and
// existing identifiers, end of file detected with defined(), #ifdef on a
// file handle, #fclose, and binary #write words.
// also-compare: fileio_data.txt
// also-compare: fileio_binary.bin
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "fileio.out" write

// Write a data file: values separated by commas, strings in quotes
#fopen Data "fileio_data.txt" write
#ifdef (Data) #write (Out, "handle defined while open\n") #end
#declare Val1 = -123.45;
#declare Vect1 = <1,2,-3>;
#write (Data, "\"A quote delimited string\",", Val1, ",", Vect1, ",\n")
#write (Data, "\"second, with a comma\",", 1e-7, ",", <0.5,-0.25,1e6>, ",\n")
#write (Data, "\"third\",", 42, ",", <1,2,3>*2, ",\n")
#fclose Data
#ifndef (Data) #write (Out, "handle undefined after #fclose\n") #end
#write (Out, "file_exists after writing ", file_exists("fileio_data.txt"), "\n")

// Append to it
#fopen Data "fileio_data.txt" append
#write (Data, "\"appended\",", 3.14159265358979, ",", <7,8,9>, "\n")
#fclose Data

// Read it back until the end of the file
#fopen Data "fileio_data.txt" read
#declare Row = 0;
#while (defined(Data))
  #read (Data, S, F, V)
  #if (defined(Data))
    #declare Row = Row + 1;
    #write (Out, "read row ", Row, ": [", S, "] ", str(F, 0, 9), " ", vstr(3, V, ",", 0, 9), "\n")
  #end
#end
#write (Out, "read rows ", Row, " handle defined after end ", defined(Data), "\n")
#write (Out, "variables read are global: ", S, "\n")

// A file of plain numbers, read one at a time into existing identifiers
#fopen Nums "fileio_numbers.txt" write
#for (I, 1, 5)
  #write (Nums, I * 1.5, ",")
#end
#write (Nums, "-2e3, 4\n")
#fclose Nums
#declare N = 0;
#declare Total = 0;
#declare Count = 0;
#fopen Nums "fileio_numbers.txt" read
#while (defined(Nums))
  #read (Nums, N)
  #declare Total = Total + N;
  #declare Count = Count + 1;
#end
#write (Out, "numbers read ", Count, " last ", N, " total ", Total, "\n")

// Hand-written data: signs, exponents, vectors of other sizes
#fopen Hand "fileio_hand.txt" write
#write (Hand, "  -1.5e2 , +7, .25,\n<1, 2>, <1,2,3,4>, \"x y\"\n")
#fclose Hand
#fopen Hand "fileio_hand.txt" read
#read (Hand, H1, H2, H3)
#read (Hand, H4, H5, H6)
#fclose Hand
#write (Out, "hand-written floats ", H1, " ", H2, " ", H3, "\n")
#write (Out, "hand-written vectors ", H4, " ", H5, " string [", H6, "]\n")

// Write of every value type; the data file itself is compared too
#fopen Data "fileio_data.txt" append
#write (Data, "floats ", 0, " ", -0.5, " ", 1/3, " ", 2e20, " ", 123456789, "\n")
#write (Data, "vectors ", <1,2>, " ", <1,2,3,4>, " ", <0.1,0.2,0.3,0.4,0.5>*1, "\n")
#write (Data, "strings ", "a", "b", concat("c", "d"), str(5, 3, 1), "\n")
#write (Data, "no newline at the end")
#fclose Data

// Binary words; the file is compared byte by byte
#fopen Bin "fileio_binary.bin" write
#write (Bin, uint8 65, uint8 66, "text", uint8 10)
#write (Bin, uint8 0, uint8 255, uint8 -1, uint8 300, uint8 2.5, uint8 3.5, uint8 2.4999, uint8 -0.6)
#write (Bin, sint8 -1, sint8 -128, sint8 -200, sint8 127, sint8 200, sint8 -2.5, sint8 -3.5)
#write (Bin, uint16be 258, uint16le 258, uint16be 70000, uint16le -5)
#write (Bin, sint16be -2, sint16le -2, sint16be 40000, sint16le -40000)
#write (Bin, sint32be 16909060, sint32le 16909060, sint32be -1, sint32le 3e9, sint32be -3e9)
#write (Bin, uint16be <1,2,3>, uint8 <1,2,3,4,5>, uint8 64+1)
#write (Bin, sint16le 1, 2, sint16le 3)
#fclose Bin
#write (Out, "binary file written\n")
#fclose Out
