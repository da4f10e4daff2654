/* unterminated /* nested 
"unterminated string
