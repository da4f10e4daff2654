#macro M(A) M(M(A)) #end
M(1)
